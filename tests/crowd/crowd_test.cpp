// Crowd runs on the committed graph, checked on their records by this test's own frame-by-frame scan.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <stdexcept>
#include <fstream>
#include <sstream>

#include "files.h"
#include "mobb/crowd/broad_phase.h"
#include "mobb/crowd/crowd.h"
#include "mobb/crowd/worker_pool.h"

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
    return {s.choice_points, s.candidates, s.queries, s.hits, s.tests2d, s.tests3d, s.samples, s.root_rejected,
            s.time_pairs, s.pruned, s.fallbacks, s.outside, s.contacts, s.contacts_unexcused, s.reevaluated};
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
            s += std::to_string(c.agent) + ":" + std::to_string(c.taken) + (c.fallback ? "F" : "") + ":" + std::to_string(c.queries) + " ";
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
        EXPECT_EQ(collide(fixture().trees[std::size_t(q.clip_a)], q.pa, fixture().trees[std::size_t(q.clip_b)], q.pb), q.hit);
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
                                          other.place.t0, other.place.t0 + g.clips[std::size_t(other.clip)].path.duration()));
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
            EXPECT_TRUE(record_to_text(r.record, summary_json(r.summary)) == text) << to_string(select) << ", " << threads << " threads";
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
            const auto at = std::find_if(own.begin(), own.end(), [&](const PlacedClip& p) { return p.commit == std::int64_t(n); });
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
                const bool stopped = !k.against.empty() && k.against.back().hit && select == Selection::Avoid && !cp.fallback;
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

TEST(WorkerPool, RunsEveryIndexOnceAndRethrowsTheLowestError) {
    for (int threads : {1, 2, 5}) {
        WorkerPool pool(threads);
        EXPECT_EQ(pool.size(), threads);
        for (std::size_t grain : {1u, 3u, 64u}) {
            std::vector<std::atomic<int>> seen(1000);
            std::vector<int> worker(seen.size(), -1);
            pool.for_each(seen.size(), [&](std::size_t i, int w) {
                ++seen[i];
                worker[i] = w;
            }, grain);
            for (std::size_t i = 0; i < seen.size(); ++i) {
                ASSERT_EQ(seen[i].load(), 1) << i;
                ASSERT_TRUE(worker[i] >= 0 && worker[i] < threads);
            }
        }
        try {
            pool.for_each(100, [](std::size_t i, int) {
                if (i % 10 == 7) throw std::runtime_error(std::to_string(i));
            });
            ADD_FAILURE() << "no exception";
        } catch (const std::runtime_error& e) {
            EXPECT_STREQ(e.what(), "7");
        }
        pool.for_each(0, [](std::size_t, int) { ADD_FAILURE(); });
    }
    EXPECT_THROW(WorkerPool(0), std::invalid_argument);
}

// Queries from several threads at once (the crowd's parallel choice points) agree with a scan of all
// boxes; expired items are neither reported nor counted.
TEST(BroadPhase, ConcurrentQueriesAndExpiry) {
    BroadPhase bp(2.0, 20, 20);
    std::vector<SpaceTimeBox> boxes;
    for (int i = 0; i < 400; ++i) {
        const double x = double((i * 37) % 26) - 3, y = double((i * 53) % 26) - 3;  // some beyond the flat cells
        boxes.push_back({x, y, x + 0.5 + (i % 5), y + 0.5 + (i % 3), i % 7, 8 + i % 11});
        bp.insert(i, i % 9, boxes.back());
    }
    bp.expire(10);
    std::size_t live = 0;
    for (const SpaceTimeBox& b : boxes) live += b.f1 > 10;
    EXPECT_EQ(bp.size(), live);
    WorkerPool pool(4);
    std::vector<int> wrong(boxes.size(), 0);
    pool.for_each(boxes.size(), [&](std::size_t q, int) {
        SpaceTimeBox box = boxes[q];
        box.f0 = 10;
        std::vector<int> got, want;
        bp.query(box, int(q % 9), got);
        for (std::size_t i = 0; i < boxes.size(); ++i)
            if (int(i % 9) != int(q % 9) && boxes[i].f1 > 10 && boxes[i].overlaps(box)) want.push_back(int(i));
        wrong[q] = got != want;
    });
    EXPECT_EQ(std::count(wrong.begin(), wrong.end(), 1), 0);
    bp.insert(1000, 0, {0, 0, 1, 1, 0, 9});  // ends before the expiry frame: dropped
    std::vector<int> out;
    bp.query({0, 0, 1, 1, 10, 20}, 1, out);
    EXPECT_EQ(std::count(out.begin(), out.end(), 1000), 0);
}

// A frame's commits inserted at once by several workers give the grid that inserting them one by one
// gives: same answers to every query, same size, expired items still dropped.
TEST(BroadPhase, InsertAllMatchesInsertingOneByOne) {
    BroadPhase one(2.0, 20, 20), all(2.0, 20, 20);
    for (BroadPhase* bp : {&one, &all}) {
        bp->insert(0, 1, {1, 1, 3, 3, 0, 5});  // expires before the batch: its cells get compacted
        bp->expire(6);
    }
    std::vector<BroadPhase::Insertion> batch;
    for (int i = 1; i < 300; ++i) {
        const double x = double((i * 41) % 30) - 5, y = double((i * 29) % 30) - 5;  // some beyond the flat cells
        batch.push_back({i, i % 7, {x, y, x + 0.3 + (i % 6), y + 0.4 + (i % 4), 6, 7 + i % 13}});
    }
    batch.push_back({300, 2, {0, 0, 1, 1, 0, 6}});  // ends by the expiry frame: dropped by both
    for (const auto& it : batch) one.insert(it.id, it.owner, it.box);
    WorkerPool pool(3);
    all.insert_all(batch, pool);
    EXPECT_EQ(all.size(), one.size());
    EXPECT_EQ(all.size(), batch.size() - 1);
    int differing = 0;
    for (const auto& it : batch) {
        std::vector<int> a, b;
        one.query(it.box, it.owner, a);
        all.query(it.box, it.owner, b);
        differing += a != b;
    }
    EXPECT_EQ(differing, 0);
    std::vector<int> out;
    all.query({-10, -10, 40, 40, 0, 100}, -1, out);
    EXPECT_EQ(out.size(), batch.size() - 1);
}

}  // namespace
}  // namespace mobb::crowd
