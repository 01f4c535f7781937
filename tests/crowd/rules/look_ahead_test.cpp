// The look-ahead (src/crowd/rules/look_ahead.h) on hand-built situations: a barrier a few metres ahead that
// the straight walks run into in their third clip; its budget; refused first clips; the learned
// times to go; a crowd whose agents reach their goals sooner with it than without it; and the rule
// called alone on a state built by hand (rule_scene.h), ordering candidates round one who stands.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <random>

#include "committed_graph.h"
#include "mobb/crowd/metrics/metrics.h"
#include "mobb/crowd/scenario/scenario.h"
#include "mobb/crowd/sim/crowd.h"
#include "plan/choice_queries.h"
#include "plan/learned_cost.h"
#include "rule_scene.h"
#include "rules/look_ahead.h"

namespace mobb::crowd {
namespace {

const MotionGraph& graph() { return test::committed_graph(); }

// The goal 12 m ahead (+x); a barrier across x in [4.5, 5.5] for |y| < 2.5: walking straight on (about
// 1.8 m a clip) meets it in the third clip; the way round turns before.
struct Barrier {
    double seconds_to_go(const Placement& p) const { return std::hypot(12.0 - p.x, p.y) / 1.0; }
    bool free(const SearchStep& step) const {
        const Rigid2 m = Rigid2::of(step.place);
        for (const Sample& x : graph().clips[std::size_t(step.clip)].path.samples) {
            const double px = m.apply_x(x.x, x.y), py = m.apply_y(x.x, x.y);
            if (px + x.r > 4.5 && px - x.r < 5.5 && std::abs(py) - x.r < 2.5) return false;
        }
        return true;
    }
};

// The successors of a walking clip: candidates of an agent walking along +x from the origin.
std::vector<int> walking_candidates(const MotionGraph& g) {
    for (int c = 0; c < int(g.clips.size()); ++c)
        if (kind_of(g.clips[std::size_t(c)], c) == ClipKind::Walk && g.clips[std::size_t(c)].successors.size() > 8)
            return g.clips[std::size_t(c)].successors;
    return {};
}

TEST(LookAhead, FindsAFreeSequenceAndRanksDeadEndsBehindIt) {
    const MotionGraph& g = graph();
    const std::vector<int> first = walking_candidates(g);
    ASSERT_FALSE(first.empty());
    const Barrier b;
    const Placement base{0, 0, 0, 0};
    LookAhead search;
    const LookAheadLimits limits{3, 400, 2.0};
    const auto& score = search.search(
        g, first, base, 0, limits, [&](const SearchStep& s) { return b.free(s); },
        [&](const Placement& p) { return b.seconds_to_go(p); });
    EXPECT_LE(search.tested(), limits.budget);
    int best = 0;
    for (int k = 1; k < int(score.size()); ++k)
        if (score[std::size_t(k)] < score[std::size_t(best)]) best = k;
    // The best sequence is whole and every clip of it free.
    const std::vector<SearchStep> seq = search.sequence(best);
    ASSERT_EQ(seq.size(), 3u);
    for (const SearchStep& s : seq) EXPECT_TRUE(b.free(s));
    // A first clip free itself that leads only into the barrier ranks behind it.
    int dead = 0;
    for (int k = 0; k < int(score.size()); ++k) {
        if (!search.sequence(k).empty() || !b.free({first[std::size_t(k)], base, 0})) continue;
        ++dead;
        EXPECT_GT(score[std::size_t(k)], score[std::size_t(best)]) << k;
    }
    EXPECT_GT(dead, 0);
}

TEST(LookAhead, KeepsToItsBudgetAndRanksRefusedFirstClipsLast) {
    const MotionGraph& g = graph();
    const std::vector<int> first = walking_candidates(g);
    const Placement base{0, 0, 0, 0};
    int asked = 0;
    LookAhead search;
    // Nothing to go: the first clips, the shortest sequences, are tested before any second clip.
    const int budget = int(first.size()) + 5;
    const auto& score = search.search(
        g, first, base, 0, {3, budget, 2.0},
        [&](const SearchStep& s) {
            ++asked;
            return s.clip != first[0];  // the first candidate's clip is refused wherever it is
        },
        [](const Placement&) { return 0.0; });
    EXPECT_EQ(asked, budget);
    EXPECT_EQ(search.tested(), budget);
    EXPECT_EQ(score[0], std::numeric_limits<double>::infinity());
    for (std::size_t k = 1; k < score.size(); ++k) EXPECT_LT(score[k], std::numeric_limits<double>::infinity());
}

TEST(LookAhead, ADeadEndRanksBehindItsBestFreeStep) {
    const MotionGraph& g = graph();
    const std::vector<int> first = walking_candidates(g);
    const Placement base{0, 0, 0, 0};
    LookAhead search;
    const double dead_end = 5.0;
    // Every first clip is free, nothing after it is: each candidate's score is its own plus dead_end.
    const auto to_go = [](const Placement& p) { return std::hypot(30.0 - p.x, p.y); };
    const auto& score = search.search(
        g, first, base, 0, {3, 10000, dead_end}, [](const SearchStep& s) { return s.frame == 0; }, to_go);
    for (std::size_t k = 0; k < first.size(); ++k) {
        const Placement end = g.next(base, first[k]);
        const double own = double(g.clips[std::size_t(first[k])].path.size()) * g.dt() + to_go(end);
        EXPECT_NEAR(score[k], own + dead_end, 1e-9);
        EXPECT_TRUE(search.sequence(int(k)).empty());
    }
}

// A lower bound of the time to go (LookAhead::search's `bound`) changes how often to_go is computed, never
// the search: the same steps tested, scores, sequences and learned times, to the bit, whether the budget
// runs out or not and however loose the bound (a bound as loose as 0 estimates every step, as before).
TEST(LookAhead, ABoundGivesTheSameSearchWithFewerEstimates) {
    const MotionGraph& g = graph();
    const std::vector<int> first = walking_candidates(g);
    const Barrier b;
    const Placement base{0, 0, 0, 0};
    const auto free = [&](const SearchStep& s) { return b.free(s); };
    int estimates = 0;
    const LookAhead::ToGo to_go = [&](const Placement& p) { return ++estimates, b.seconds_to_go(p); };
    const std::vector<LookAhead::ToGo> bounds{
        [&](const Placement& p) { return 0.5 * b.seconds_to_go(p); },
        [&](const Placement& p) { return b.seconds_to_go(p) - 1.0; },
        [](const Placement&) { return 0.0; },
    };
    for (int budget : {40, 400}) {
        const LookAheadLimits limits{3, budget, 2.0};
        LookAhead eager, lazy;
        estimates = 0;
        const std::vector<double> want = eager.search(g, first, base, 0, limits, free, to_go);
        const int eager_estimates = estimates;
        std::vector<std::array<double, 3>> want_learned, got_learned;
        eager.learned(want[0], want_learned);
        for (std::size_t j = 0; j < bounds.size(); ++j) {
            estimates = 0;
            EXPECT_EQ(lazy.search(g, first, base, 0, limits, free, to_go, bounds[j]), want) << budget << " " << j;
            EXPECT_LE(estimates, eager_estimates) << budget << " " << j;
            if (j == 1) {
                EXPECT_LT(estimates, eager_estimates) << "a close bound leaves steps unestimated";
            }
            EXPECT_EQ(lazy.tested(), eager.tested());
            got_learned.clear();
            lazy.learned(want[0], got_learned);
            EXPECT_EQ(got_learned, want_learned);
            for (int k = 0; k < int(first.size()); ++k) {
                const std::vector<SearchStep> a = eager.sequence(k), c = lazy.sequence(k);
                ASSERT_EQ(a.size(), c.size()) << k;
                for (std::size_t i = 0; i < a.size(); ++i) {
                    EXPECT_EQ(a[i].clip, c[i].clip);
                    EXPECT_EQ(a[i].frame, c[i].frame);
                    EXPECT_EQ(a[i].place.x, c[i].place.x);
                    EXPECT_EQ(a[i].place.theta, c[i].place.theta);
                }
            }
        }
    }
}

TEST(LearnedCost, KeepsTheLargestPerCell) {
    LearnedCost c;
    EXPECT_EQ(c.at(1.1, -0.2), 0.0);
    c.raise(1.1, -0.2, 5.0);
    c.raise(1.2, -0.1, 3.0);  // the same 0.5 m cell
    EXPECT_EQ(c.at(1.4, -0.4), 5.0);
    EXPECT_EQ(c.at(1.6, -0.2), 0.0);  // the next cell in x
    EXPECT_EQ(c.at(1.1, 0.1), 0.0);   // the next cell in y
    c.raise(-700.3, 900.2, 7.0);
    EXPECT_EQ(c.at(-700.3, 900.2), 7.0);
}

// Thousands of cells, each raised several times, through the table's growth: the largest per cell, 0
// where nothing was; and nothing after clear().
TEST(LearnedCost, KeepsEveryCellThroughGrowth) {
    LearnedCost c;
    std::map<std::pair<int, int>, double> want;
    std::mt19937_64 rng(5);
    std::uniform_int_distribution<int> cell(-60, 60);
    std::uniform_real_distribution<double> seconds(0, 100);
    for (int k = 0; k < 20000; ++k) {
        const int ix = cell(rng), iy = cell(rng);
        const double s = seconds(rng);
        c.raise((ix + 0.25) * LearnedCost::kCell, (iy + 0.75) * LearnedCost::kCell, s);
        double& w = want[{ix, iy}];
        w = std::max(w, s);
    }
    for (int ix = -61; ix <= 61; ++ix)
        for (int iy = -61; iy <= 61; ++iy) {
            const auto it = want.find({ix, iy});
            ASSERT_EQ(c.at((ix + 0.5) * LearnedCost::kCell, (iy + 0.5) * LearnedCost::kCell),
                      it == want.end() ? 0.0 : it->second)
                << ix << ", " << iy;
        }
    c.clear();
    EXPECT_EQ(c.at(0.25 * LearnedCost::kCell, 0.75 * LearnedCost::kCell), 0.0);
}

// A whole crowd: the twenty agents of a circle cross its centre. With the look-ahead they reach their
// goals sooner than choosing one clip at a time, on the mean and the last of them (bench/results/crowd.md
// has every scenario). (Not with less idle: keeping right in the open, they stand less without it.)
TEST(LookAhead, ACircleOfAgentsReachesItsGoalsSoonerWithIt) {
    const Scenario s = load_scenario(default_scenario_folder() + "/circle_20.json");
    CrowdOptions with = scenario_options(s), without = with;
    without.tuning.look_ahead.on = false;
    const NarrowPhase narrow = NarrowPhase::sweep(graph());
    const CrowdMetrics a = crowd_metrics(run_crowd(graph(), narrow, with).record, graph());
    const CrowdMetrics b = crowd_metrics(run_crowd(graph(), narrow, without).record, graph());
    EXPECT_EQ(a.reached, a.goal_agents);
    EXPECT_LT(a.mean_time_to_goal, b.mean_time_to_goal);
    EXPECT_LT(a.max_time_to_goal, b.max_time_to_goal);
}

// The plan a goal agent keeps (ChoicePoint::intended): the clips after the one taken, each a successor of
// the one before and starting where and when it ends, and the record keeps it.
TEST(LookAhead, TheIntendedClipsFollowTheTakenOneInTheRecord) {
    const MotionGraph& g = graph();
    const Scenario s = load_scenario(default_scenario_folder() + "/circle_20.json");
    CrowdOptions o = scenario_options(s);
    o.seconds = 20;
    const Record r = run_crowd(g, NarrowPhase::sweep(g), o).record;
    int planned = 0;
    for (const ChoicePoint& c : r.choices) {
        if (c.intended.empty()) continue;
        ++planned;
        int prev = c.taken;
        std::int64_t frame = c.frame;
        for (const FramedClip& e : c.intended) {
            const auto& next = g.clips[std::size_t(prev)].successors;
            ASSERT_NE(std::find(next.begin(), next.end(), e.clip), next.end());
            frame += std::int64_t(g.clips[std::size_t(prev)].path.size());
            ASSERT_EQ(e.frame, frame);
            prev = e.clip;
        }
    }
    EXPECT_GT(planned, 20);
    const std::string file = testing::TempDir() + "/intended_record.json";
    std::ofstream(file) << record_to_text(r, "{}");
    const Record back = load_record(file);
    ASSERT_EQ(back.choices.size(), r.choices.size());
    for (std::size_t k = 0; k < r.choices.size(); ++k) {
        ASSERT_EQ(back.choices[k].intended.size(), r.choices[k].intended.size());
        for (std::size_t i = 0; i < r.choices[k].intended.size(); ++i)
            EXPECT_EQ(back.choices[k].intended[i].clip, r.choices[k].intended[i].clip);
    }
}

// ---- The rule (look_ahead()) on a state built by hand (rule_scene.h) ----

using rule_test::Scene;
using rule_test::walks;

// A goal agent at the origin facing its goal 10 m east, one agent standing 3 m ahead on its way, and the
// candidates of an agent walking (the successors of a walk with many) in the goal policy's order.
struct GoalAhead {
    Scene scene{Selection::Goal, {}, {{10, 0}}};
    const Placement at{0, 0, 0, 0};
    ChoiceBase base;
    ChoiceSite site;
    std::vector<int> policy;
    Piece standing;
    ChoiceQueries q;
    LookAheadState io;

    GoalAhead() {
        base = {scene.add_agent(at), 0, at, Rigid2::of(at)};
        scene.agents[std::size_t(base.agent)].goals = {{10, 0}};
        scene.stand(base.agent);
        scene.stand(scene.add_agent({3, 0, M_PI, 0}));
        standing = scene.pieces.back();
        site = {base.agent, at, std::array<double, 2>{10, 0}, true, 0, false, std::nullopt, {}};
        for (int walk : walks(scene.g))
            if (policy.size() < 8) policy = scene.g.clips[std::size_t(walk)].successors;
        scene.policy->order(site, policy);
        q.start(base.agent, 0);
    }
    // The look-ahead with `t`, a budget that takes every candidate's search to the horizon by default.
    std::vector<int> search(LookAheadTuning t = {true, 2000}) {
        std::vector<int> order = policy;
        look_ahead(t, {}, scene.state(), base, site, q, order, io);
        return order;
    }
};

TEST(RuleUnits, LookAheadOrdersTheCandidatesByTheirBestSequence) {
    GoalAhead g;
    const std::vector<int> order = g.search();
    ASSERT_TRUE(g.io.searched);
    EXPECT_GT(g.q.point().queries, 0u) << "its steps are tested, and counted for the choice point";
    std::vector<int> sorted = order, before = g.policy;
    std::sort(sorted.begin(), sorted.end()), std::sort(before.begin(), before.end());
    EXPECT_EQ(sorted, before) << "the same candidates";
    for (std::size_t k = 0; k < order.size(); ++k) EXPECT_EQ(order[k], g.policy[std::size_t(g.io.ranked[k].second)]);
    for (std::size_t k = 1; k < order.size(); ++k)
        EXPECT_LE(g.io.ranked[k - 1].first, g.io.ranked[k].first) << "the best sequence first";
    ASSERT_FALSE(g.io.learned.empty());
    EXPECT_EQ(g.io.learned.back()[0], g.at.x) << "the time to go learned where it stands";
    EXPECT_EQ(g.io.learned.back()[2], g.io.ranked[0].first);
    // Within the default budget, too, the search keeps to it.
    g.search({});
    EXPECT_LE(g.io.search.tested(), LookAheadTuning{}.budget);
}

// Every sequence found is whole and clear of the one standing, and some walks lead only into it; the
// first found in the order is what the choice point intends after its first clip.
TEST(RuleUnits, LookAheadSequencesGoRoundOneStandingInTheWay) {
    GoalAhead g;
    const std::vector<int> order = g.search();
    const CrowdState s = g.scene.state();
    int whole = 0, first = -1;
    for (std::size_t k = 0; k < order.size(); ++k) {
        const std::vector<SearchStep> seq = g.io.search.sequence(g.io.ranked[k].second);
        if (seq.empty()) continue;
        ++whole;
        if (first < 0) first = int(k);
        ASSERT_EQ(int(seq.size()), g.scene.options.tuning.goal.horizon);
        EXPECT_EQ(seq[0].clip, order[k]);
        for (const SearchStep& step : seq) {
            Piece p;
            p.clip = frame_clip(s, step.clip, step.place, Rigid2::of(step.place), step.frame);
            EXPECT_FALSE(pieces_collide(s, p, g.standing, nullptr));
        }
    }
    ASSERT_GT(whole, 0);
    EXPECT_LT(whole, int(order.size())) << "some walks lead only into the one standing";
    std::vector<SearchStep> intended;
    intended_after(g.io, first, intended);
    const std::vector<SearchStep> seq = g.io.search.sequence(g.io.ranked[std::size_t(first)].second);
    ASSERT_EQ(intended.size(), seq.size() - 1);
    EXPECT_EQ(intended[0].clip, seq[1].clip);
}

TEST(RuleUnits, LookAheadOffKeepsThePolicysOrder) {
    GoalAhead g;
    g.search();
    EXPECT_EQ(g.search({false}), g.policy);
    EXPECT_FALSE(g.io.searched);
    std::vector<SearchStep> intended;
    intended_after(g.io, 0, intended);
    EXPECT_TRUE(intended.empty());
}

}  // namespace
}  // namespace mobb::crowd
