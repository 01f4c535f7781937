// Crowd runs on the committed graph, checked on their records by this test's own frame-by-frame scan.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "files.h"
#include "mobb/crowd/broad_phase.h"
#include "mobb/crowd/crowd.h"

namespace mobb::crowd {
namespace {

using test::temp_file;

const std::string kGraph = std::string(MOBB_SOURCE_DIR) + "/assets/graphs/cmu_locomotion.json";

struct Fixture {
    MotionGraph graph = load_graph(kGraph);
    std::vector<Tree> trees = build_trees(graph, {});
};

Fixture& fixture() {
    static Fixture f;
    return f;
}

CrowdRun run(int agents, double seconds, std::uint64_t seed, Selection select, bool log = false, int threads = 1) {
    CrowdOptions o;
    o.agents = agents;
    o.seconds = seconds;
    o.seed = seed;
    o.select = select;
    o.log_queries = log;
    o.threads = threads;
    return run_crowd(fixture().graph, fixture().trees, o);
}

// The broad-phase box of a placed clip (crowd.h: its root positions' box padded by its largest
// radius), computed here from every sample, independently of the simulation's convex hulls.
SpaceTimeBox box_of(int clip, const Placement& p, std::int64_t start) {
    const Path& path = fixture().graph.clips[std::size_t(clip)].path;
    const Rigid2 m = Rigid2::of(p);
    SpaceTimeBox b{1e300, 1e300, -1e300, -1e300, start, start + std::int64_t(path.size())};
    double r = 0;
    for (const Sample& s : path.samples) {
        const double x = m.apply_x(s.x, s.y), y = m.apply_y(s.x, s.y);
        b.x0 = std::min(b.x0, x), b.y0 = std::min(b.y0, y);
        b.x1 = std::max(b.x1, x), b.y1 = std::max(b.y1, y);
        r = std::max(r, s.r);
    }
    b.x0 -= r, b.y0 -= r, b.x1 += r, b.y1 += r;
    return b;
}

// Every counter of a summary but the times.
std::vector<std::uint64_t> counters(const CrowdSummary& s) {
    return {s.choice_points, s.candidates,         s.queries,    s.hits,   s.tests2d,   s.tests3d,
            s.samples,       s.root_rejected,      s.time_pairs, s.pruned, s.fallbacks, s.outside,
            s.contacts,      s.contacts_unexcused, s.reevaluated};
}

std::string logged_text(const std::vector<LoggedQuery>& log) {
    std::ostringstream out;
    out.precision(17);
    for (const LoggedQuery& q : log)
        out << q.choice << " " << q.candidate << " " << q.clip_a << " " << q.clip_b << " " << q.pa.x << " " << q.pa.y
            << " " << q.pa.theta << " " << q.pa.t0 << " " << q.pb.x << " " << q.pb.y << " " << q.pb.theta << " "
            << q.pb.t0 << " " << q.hit << "\n";
    return out.str();
}

// Contacts at every frame between every pair, not excused by a fallback clip of either agent.
int unexcused_contacts(const Record& r, int& all) {
    auto fallback = [&](int a, std::int64_t f) {
        for (const PlacedClip& c : r.tracks[std::size_t(a)].clips) {
            const std::int64_t n = std::int64_t(fixture().graph.clips[std::size_t(c.clip)].path.size());
            if (c.start <= f && f < c.start + n) return c.fallback;
        }
        ADD_FAILURE() << "agent " << a << " has no clip at frame " << f;
        return false;
    };
    int bad = 0;
    all = 0;
    for (std::int64_t f = 0; f < r.frames; ++f)
        for (std::size_t a = 0; a < r.tracks.size(); ++a)
            for (std::size_t b = a + 1; b < r.tracks.size(); ++b) {
                const auto& p = r.tracks[a].samples[std::size_t(f)];
                const auto& q = r.tracks[b].samples[std::size_t(f)];
                const double dx = p[1] - q[1], dy = p[2] - q[2], s = p[3] + q[3];
                if (dx * dx + dy * dy >= s * s) continue;
                ++all;
                if (!fallback(int(a), f) && !fallback(int(b), f)) ++bad;
            }
    return bad;
}

TEST(Crowd, AvoidRunHasNoContactsOutsideFallbacks) {
    const CrowdRun c = run(30, 20, 7, Selection::Avoid);
    const Record& r = c.record;
    ASSERT_EQ(r.tracks.size(), 30u);
    ASSERT_EQ(r.frames, 600);
    for (const AgentTrack& t : r.tracks) {
        ASSERT_EQ(t.samples.size(), 600u);
        for (std::size_t f = 0; f < t.samples.size(); ++f) EXPECT_DOUBLE_EQ(t.samples[f][0], double(f) / 30.0);
    }
    int all = 0;
    EXPECT_EQ(unexcused_contacts(r, all), 0);
    EXPECT_EQ(std::uint64_t(all), c.summary.contacts);
    EXPECT_EQ(c.summary.contacts_unexcused, 0u);
    EXPECT_GT(c.summary.queries, 0u);
    EXPECT_GT(c.summary.pruned, 0u);
}

TEST(Crowd, ClipsFollowTheGraphOnTheFrameGrid) {
    const CrowdRun c = run(10, 15, 3, Selection::Avoid);
    const MotionGraph& g = fixture().graph;
    for (const AgentTrack& t : c.record.tracks)
        for (std::size_t k = 1; k < t.clips.size(); ++k) {
            const PlacedClip &a = t.clips[k - 1], &b = t.clips[k];
            const auto& succ = g.clips[std::size_t(a.clip)].successors;
            EXPECT_NE(std::find(succ.begin(), succ.end(), b.clip), succ.end());
            EXPECT_EQ(b.start, a.start + std::int64_t(g.clips[std::size_t(a.clip)].path.size()));
            EXPECT_EQ(b.place.t0, double(b.start) * g.dt());
            const Placement n = g.next(a.place, a.clip);
            EXPECT_NEAR(b.place.x, n.x, 1e-9);
            EXPECT_NEAR(b.place.theta, n.theta, 1e-9);
        }
}

TEST(Crowd, SameSeedSameRecord) {
    const std::string a = record_to_text(run(20, 10, 42, Selection::Avoid).record, "");
    const std::string b = record_to_text(run(20, 10, 42, Selection::Avoid).record, "");
    const std::string c = record_to_text(run(20, 10, 43, Selection::Avoid).record, "");
    EXPECT_EQ(a, b);
    EXPECT_NE(a, c);
}

TEST(Crowd, EveryTreeTypeGivesTheSameCrowd) {
    CrowdOptions o;
    o.agents = 25;
    o.seconds = 10;
    o.seed = 5;
    // Same answers, so the same decisions; only the work counted differs.
    auto decisions = [](const Record& r) {
        std::string s;
        for (const ChoicePoint& c : r.choices) {
            s += std::to_string(c.agent) + ":" + std::to_string(c.taken) + (c.fallback ? "F" : "") + ":" +
                 std::to_string(c.queries) + " ";
            for (const Candidate& k : c.candidates) s += std::to_string(k.hits) + ",";
        }
        return s;
    };
    const Record ref = run_crowd(fixture().graph, fixture().trees, o).record;
    for (TreeType t : {TreeType::Umobb, TreeType::Hybrid1, TreeType::Hybrid2, TreeType::Mobb1, TreeType::Umobb1}) {
        TreeOptions to;
        to.type = t;
        const Record r = run_crowd(fixture().graph, build_trees(fixture().graph, to), o).record;
        EXPECT_EQ(decisions(r), decisions(ref)) << to_string(t);
        EXPECT_TRUE(r.tracks.back().samples == ref.tracks.back().samples) << to_string(t);
    }
}

TEST(Crowd, RandomModeRunsEveryQuery) {
    const CrowdRun c = run(30, 10, 1, Selection::Random, true);
    std::uint64_t per_candidate = 0;
    for (const ChoicePoint& cp : c.record.choices) {
        EXPECT_FALSE(cp.fallback);
        for (const Candidate& k : cp.candidates) per_candidate += std::uint64_t(k.queries);
    }
    EXPECT_EQ(per_candidate, c.summary.queries);
    EXPECT_EQ(c.queries.size(), c.summary.queries);
    // Logged queries replay to the same answers.
    for (std::size_t k = 0; k < c.queries.size(); k += 7) {
        const LoggedQuery& q = c.queries[k];
        EXPECT_EQ(collide(fixture().trees[std::size_t(q.clip_a)], q.pa, fixture().trees[std::size_t(q.clip_b)], q.pb),
                  q.hit);
    }
}

TEST(Crowd, RecordRoundTripsThroughAFile) {
    const CrowdRun c = run(5, 5, 9, Selection::Avoid);
    const std::string file = temp_file("crowd_record.json");
    {
        std::ofstream f(file);
        f << record_to_text(c.record, summary_json(c.summary));
    }
    const Record r = load_record(file);
    std::remove(file.c_str());
    ASSERT_EQ(r.tracks.size(), c.record.tracks.size());
    EXPECT_EQ(r.frames, c.record.frames);
    EXPECT_EQ(r.tracks[2].samples[17], c.record.tracks[2].samples[17]);
    EXPECT_EQ(r.choices.size(), c.record.choices.size());
    for (std::size_t k = 0; k < r.choices.size(); ++k)
        for (std::size_t j = 0; j < r.choices[k].candidates.size(); ++j) {
            const auto &x = r.choices[k].candidates[j].against, &y = c.record.choices[k].candidates[j].against;
            ASSERT_EQ(x.size(), y.size());
            for (std::size_t q = 0; q < x.size(); ++q)
                EXPECT_TRUE(x[q].agent == y[q].agent && x[q].index == y[q].index && x[q].hit == y[q].hit);
        }
    EXPECT_EQ(frame_contacts(r).size(), c.summary.contacts);
}

// Each candidate's recorded queries name committed clips of other agents overlapping it in time, and
// rerunning them gives the recorded answers, which add up to its hits.
TEST(Crowd, RecordedQueriesReplayToTheirAnswers) {
    const CrowdRun c = run(30, 15, 11, Selection::Avoid);
    const MotionGraph& g = fixture().graph;
    const Record& r = c.record;
    std::uint64_t replayed = 0;
    for (const ChoicePoint& cp : r.choices) {
        const auto& own = r.tracks[std::size_t(cp.agent)].clips;
        auto at = std::find_if(own.begin(), own.end(), [&](const PlacedClip& p) { return p.start == cp.frame; });
        ASSERT_NE(at, own.end());
        for (const Candidate& k : cp.candidates) {
            EXPECT_EQ(k.against.size(), std::size_t(k.queries));
            int hits = 0;
            for (const CandidateQuery& q : k.against) {
                ASSERT_NE(q.agent, cp.agent);
                const PlacedClip& other = r.tracks[std::size_t(q.agent)].clips[std::size_t(q.index)];
                EXPECT_LT(other.commit, at->commit);
                const bool hit = collide(fixture().trees[std::size_t(k.clip)], at->place,
                                         fixture().trees[std::size_t(other.clip)], other.place);
                EXPECT_EQ(hit, q.hit);
                EXPECT_TRUE(times_overlap(at->place.t0, at->place.t0 + g.clips[std::size_t(k.clip)].path.duration(),
                                          other.place.t0,
                                          other.place.t0 + g.clips[std::size_t(other.clip)].path.duration()));
                hits += q.hit;
                ++replayed;
            }
            EXPECT_EQ(hits, k.hits);
        }
    }
    EXPECT_GT(replayed, 100u);
}

// The choice points of a frame run in parallel and are committed in agent order; any thread count
// gives the very same record, logged queries (in the same order) and counters.
TEST(Crowd, ThreadCountDoesNotChangeTheRun) {
    for (Selection select : {Selection::Avoid, Selection::Random}) {
        // Dense enough that choice points of one frame often meet (re-evaluations) and fallbacks occur.
        const CrowdRun ref = run(60, 15, 21, select, true, 1);
        const std::string text = record_to_text(ref.record, summary_json(ref.summary));
        const std::string log = logged_text(ref.queries);
        EXPECT_GT(ref.summary.reevaluated, 0u) << to_string(select);
        if (select == Selection::Avoid) {
            EXPECT_GT(ref.summary.fallbacks, 0u);
        }
        EXPECT_EQ(ref.queries.size(), ref.summary.queries);
        for (int threads : {2, 3, 8}) {
            const CrowdRun r = run(60, 15, 21, select, true, threads);
            EXPECT_EQ(r.summary.threads, threads);
            EXPECT_TRUE(record_to_text(r.record, summary_json(r.summary)) == text)
                << to_string(select) << ", " << threads << " threads";
            EXPECT_TRUE(logged_text(r.queries) == log) << to_string(select) << ", " << threads << " threads";
            EXPECT_EQ(counters(r.summary), counters(ref.summary)) << to_string(select) << ", " << threads << " threads";
        }
    }
}

// The outcome is that of taking the choice points one by one: each candidate queried exactly the
// clips committed before its choice point (by other agents, still playing, boxes overlapping), in
// commit order, up to its first hit when it stopped there.
TEST(Crowd, EachChoiceSeesEveryEarlierCommit) {
    for (Selection select : {Selection::Avoid, Selection::Random}) {
        const CrowdRun c = run(60, 12, 4, select, false, 3);
        const Record& r = c.record;
        ASSERT_GT(c.summary.reevaluated, 0u);
        // Committed clips in commit order: (commit, agent, index).
        std::vector<std::array<std::int64_t, 3>> commits;
        for (std::size_t a = 0; a < r.tracks.size(); ++a)
            for (std::size_t k = 0; k < r.tracks[a].clips.size(); ++k)
                commits.push_back({r.tracks[a].clips[k].commit, std::int64_t(a), std::int64_t(k)});
        std::sort(commits.begin(), commits.end());
        for (std::size_t n = 0; n < r.choices.size(); ++n) {
            const ChoicePoint& cp = r.choices[n];
            const auto& own = r.tracks[std::size_t(cp.agent)].clips;
            const auto at =
                std::find_if(own.begin(), own.end(), [&](const PlacedClip& p) { return p.commit == std::int64_t(n); });
            ASSERT_NE(at, own.end());
            ASSERT_EQ(at->start, cp.frame);
            for (const Candidate& k : cp.candidates) {
                const SpaceTimeBox box = box_of(k.clip, at->place, cp.frame);
                std::vector<std::pair<int, int>> expected;
                for (const auto& [commit, b, index] : commits) {
                    if (commit >= std::int64_t(n)) break;
                    const PlacedClip& other = r.tracks[std::size_t(b)].clips[std::size_t(index)];
                    if (b != cp.agent && box_of(other.clip, other.place, other.start).overlaps(box))
                        expected.emplace_back(int(b), int(index));
                }
                ASSERT_LE(k.against.size(), expected.size());
                for (std::size_t q = 0; q < k.against.size(); ++q) {
                    EXPECT_EQ(k.against[q].agent, expected[q].first) << "choice " << n;
                    EXPECT_EQ(k.against[q].index, expected[q].second) << "choice " << n;
                }
                const bool stopped =
                    !k.against.empty() && k.against.back().hit && select == Selection::Avoid && !cp.fallback;
                const bool skipped = k.outside && select == Selection::Avoid && !cp.fallback;
                if (!stopped && !skipped) {
                    EXPECT_EQ(k.against.size(), expected.size()) << "choice " << n;
                }
            }
        }
    }
}

TEST(Crowd, RejectsImpossibleWorlds) {
    CrowdOptions o;
    o.agents = 1000;
    o.width = o.height = 5;
    EXPECT_THROW(run_crowd(fixture().graph, fixture().trees, o), std::invalid_argument);
    EXPECT_THROW(parse_selection("nearest"), std::invalid_argument);
    CrowdOptions none;
    none.threads = 0;
    EXPECT_THROW(run_crowd(fixture().graph, fixture().trees, none), std::invalid_argument);
}

}  // namespace
}  // namespace mobb::crowd
