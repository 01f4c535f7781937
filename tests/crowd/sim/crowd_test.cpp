// Crowd runs on the committed graph, checked on their records by this test's own frame-by-frame scan and
// by replaying their queries with the brute-force reference - never through the trees or the sweep.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "choice/choice.h"
#include "files.h"
#include "mobb/core/brute.h"
#include "mobb/crowd/metrics/metrics.h"
#include "mobb/crowd/scenario/scenario.h"
#include "mobb/crowd/sim/crowd.h"

namespace mobb::crowd {
namespace {

using test::temp_file;

const std::string kGraph = std::string(MOBB_SOURCE_DIR) + "/assets/graphs/cmu_locomotion.json";

struct Fixture {
    MotionGraph graph = load_graph(kGraph);
    NarrowPhase sweep = NarrowPhase::sweep(graph);
    NarrowPhase mobb = NarrowPhase::trees(graph, {});
};

Fixture& fixture() {
    static Fixture f;
    return f;
}

const Path& path_of(int clip) { return fixture().graph.clips[std::size_t(clip)].path; }

CrowdOptions wander(int agents, double seconds, std::uint64_t seed, Selection select = Selection::Wander) {
    CrowdOptions o;
    o.agents = agents;
    o.seconds = seconds;
    o.seed = seed;
    o.select = select;
    // The paper's density, 12 m^2 per agent.
    const double side = std::sqrt(12.0 * agents / 1.2);
    o.world.x1 = side;
    o.world.y1 = 1.2 * side;
    return o;
}

CrowdRun run(const CrowdOptions& o, const NarrowPhase& narrow = fixture().sweep) {
    return run_crowd(fixture().graph, narrow, o);
}

// Every counter of a summary but the times.
std::vector<std::uint64_t> counters(const CrowdSummary& s) {
    return {s.choice_points, s.candidates,         s.queries,     s.hits,    s.tests2d,      s.tests3d,
            s.samples,       s.root_rejected,      s.time_pairs,  s.pruned,  s.fallbacks,    s.fallbacks_meeting_solids,
            s.contacts,      s.contacts_unexcused, s.reevaluated, s.escapes, s.right_of_way, s.reroutes};
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

// The clip agent `a` plays at frame f (the test's own lookup).
const PlacedClip& clip_at(const Record& r, int a, std::int64_t f) {
    for (const PlacedClip& c : r.tracks[std::size_t(a)].clips)
        if (c.start <= f && f < c.start + std::int64_t(path_of(c.clip).size())) return c;
    throw std::logic_error("agent " + std::to_string(a) + " has no clip at frame " + std::to_string(f));
}

struct Scan {
    int contacts = 0, outside_fallbacks = 0;
};

// Contacts at every frame between every pair of agents, by brute force over all pairs.
Scan scan_contacts(const Record& r) {
    Scan out;
    for (std::int64_t f = 0; f < r.frames; ++f)
        for (std::size_t a = 0; a < r.tracks.size(); ++a)
            for (std::size_t b = a + 1; b < r.tracks.size(); ++b) {
                const auto& p = r.tracks[a].samples[std::size_t(f)];
                const auto& q = r.tracks[b].samples[std::size_t(f)];
                const double dx = p[1] - q[1], dy = p[2] - q[2], s = p[3] + q[3];
                if (dx * dx + dy * dy >= s * s) continue;
                ++out.contacts;
                if (!clip_at(r, int(a), f).fallback && !clip_at(r, int(b), f).fallback) ++out.outside_fallbacks;
            }
    return out;
}

// The record's samples are its clips' samples placed where the clips were committed.
void expect_samples_follow_clips(const Record& r) {
    for (std::size_t a = 0; a < r.tracks.size(); ++a)
        for (std::int64_t f = 0; f < r.frames; f += 7) {
            const PlacedClip& c = clip_at(r, int(a), f);
            const Sample& s = path_of(c.clip).samples[std::size_t(f - c.start)];
            const double cs = std::cos(c.place.theta), sn = std::sin(c.place.theta);
            const auto& got = r.tracks[a].samples[std::size_t(f)];
            EXPECT_NEAR(got[1], c.place.x + cs * s.x - sn * s.y, 1e-9);
            EXPECT_NEAR(got[2], c.place.y + sn * s.x + cs * s.y, 1e-9);
            EXPECT_EQ(got[3], s.r);
        }
}

TEST(Crowd, WanderHasNoContactAndStaysInsideTheWalls) {
    const CrowdRun c = run(wander(40, 20, 7));
    const Record& r = c.record;
    ASSERT_EQ(r.tracks.size(), 40u);
    ASSERT_EQ(r.frames, 600);
    for (const AgentTrack& t : r.tracks) {
        ASSERT_EQ(t.samples.size(), 600u);
        for (std::size_t f = 0; f < t.samples.size(); ++f) {
            const auto& s = t.samples[f];
            EXPECT_DOUBLE_EQ(s[0], double(f) / 30.0);
            // Walls: every disk inside the rectangle (touching allowed).
            EXPECT_GE(s[1] - s[3], r.world.x0 - 1e-9);
            EXPECT_LE(s[1] + s[3], r.world.x1 + 1e-9);
            EXPECT_GE(s[2] - s[3], r.world.y0 - 1e-9);
            EXPECT_LE(s[2] + s[3], r.world.y1 + 1e-9);
        }
    }
    expect_samples_follow_clips(r);
    const Scan scan = scan_contacts(r);
    EXPECT_EQ(scan.outside_fallbacks, 0);
    EXPECT_EQ(std::uint64_t(scan.contacts), c.summary.contacts);
    EXPECT_EQ(c.summary.contacts_unexcused, 0u);
    EXPECT_GT(c.summary.queries, 0u);
    EXPECT_GT(c.summary.pruned, 0u);
    // The agents walk: most of the ground a graph clip covers, on average.
    double length = 0;
    for (const AgentTrack& t : r.tracks)
        for (std::size_t f = 1; f < t.samples.size(); ++f)
            length += std::hypot(t.samples[f][1] - t.samples[f - 1][1], t.samples[f][2] - t.samples[f - 1][2]);
    EXPECT_GT(length / (40 * 20.0), 0.6) << "m/s";
}

// Disks centred on the body rather than the root (assets/graphs/cmu_locomotion_enclosing.json): the same
// guarantee, checked by brute force, walls and an obstacle included, with narrower disks than the root's.
TEST(Crowd, DisksCentredOnTheBodyKeepTheCrowdFreeOfContacts) {
    const MotionGraph body = load_graph(std::string(MOBB_SOURCE_DIR) + "/assets/graphs/cmu_locomotion_enclosing.json");
    CrowdOptions o = wander(40, 20, 7);
    o.world.obstacles = {Polygon::rectangle(5, 6, 6, 14)};
    const CrowdRun c = run_crowd(body, NarrowPhase::sweep(body), o);
    const Record& r = c.record;
    double r_body = 0, r_root = 0;
    for (std::size_t a = 0; a < r.tracks.size(); ++a)
        for (std::int64_t f = 0; f < r.frames; ++f) {
            const auto& s = r.tracks[a].samples[std::size_t(f)];
            EXPECT_GE(s[1] - s[3], r.world.x0 - 1e-9);
            EXPECT_LE(s[2] + s[3], r.world.y1 + 1e-9);
            EXPECT_FALSE(s[1] + s[3] > 5 && s[1] - s[3] < 6 && s[2] + s[3] > 6 && s[2] - s[3] < 14 &&
                         std::hypot(std::max({5 - s[1], 0.0, s[1] - 6}), std::max({6 - s[2], 0.0, s[2] - 14})) < s[3])
                << "a disk on the obstacle";
            const PlacedClip& p = clip_at(r, int(a), f);
            r_body += s[3];
            r_root += path_of(p.clip).samples[std::size_t(f - p.start)].r;
        }
    const Scan scan = scan_contacts(r);
    EXPECT_EQ(scan.contacts, 0);
    EXPECT_EQ(c.summary.contacts, 0u);
    EXPECT_GT(c.summary.choice_points, 0u);
    EXPECT_LT(r_body, 0.92 * r_root) << "the same clips' root-centred disks are wider";
}

TEST(Crowd, ClipsFollowTheGraphOnTheFrameGrid) {
    const CrowdRun c = run(wander(10, 15, 3));
    const MotionGraph& g = fixture().graph;
    for (const AgentTrack& t : c.record.tracks)
        for (std::size_t k = 1; k < t.clips.size(); ++k) {
            const PlacedClip &a = t.clips[k - 1], &b = t.clips[k];
            const auto& succ = g.clips[std::size_t(a.clip)].successors;
            EXPECT_NE(std::find(succ.begin(), succ.end(), b.clip), succ.end());
            EXPECT_EQ(b.start, a.start + std::int64_t(path_of(a.clip).size()));
            EXPECT_EQ(b.place.t0, double(b.start) * g.dt());
            const Placement n = g.next(a.place, a.clip);
            EXPECT_NEAR(b.place.x, n.x, 1e-9);
            EXPECT_NEAR(b.place.theta, n.theta, 1e-9);
        }
}

TEST(Crowd, SameSeedSameRecord) {
    const std::string a = record_to_text(run(wander(20, 10, 42)).record, "");
    const std::string b = record_to_text(run(wander(20, 10, 42)).record, "");
    const std::string c = record_to_text(run(wander(20, 10, 43)).record, "");
    EXPECT_EQ(a, b);
    EXPECT_NE(a, c);
}

// Same answers, so the same decisions, whichever exact query answers them; only the work counted differs.
TEST(Crowd, EveryNarrowPhaseGivesTheSameCrowd) {
    auto decisions = [](const Record& r) {
        std::string s;
        for (const ChoicePoint& c : r.choices) {
            s += std::to_string(c.agent) + ":" + std::to_string(c.taken) + c.outcome + ":" + std::to_string(c.queries) +
                 " ";
            for (const Candidate& k : c.candidates) s += std::to_string(k.hits) + ",";
        }
        return s;
    };
    for (Selection select : {Selection::Wander, Selection::Random}) {
        const CrowdOptions o = wander(25, 10, 5, select);
        const Record ref = run(o).record;
        EXPECT_EQ(ref.tree, "sweep");
        for (TreeType t : {TreeType::Mobb, TreeType::Umobb, TreeType::Hybrid1, TreeType::Hybrid2, TreeType::Mobb1,
                           TreeType::Umobb1}) {
            TreeOptions to;
            to.type = t;
            const CrowdRun r = run(o, NarrowPhase::trees(fixture().graph, to));
            EXPECT_EQ(r.record.tree, to_string(t));
            EXPECT_EQ(decisions(r.record), decisions(ref)) << to_string(t);
            EXPECT_TRUE(r.record.tracks.back().samples == ref.tracks.back().samples) << to_string(t);
            EXPECT_GT(r.summary.tests2d + r.summary.tests3d, 0u) << "the trees count their box tests";
        }
    }
}

// Each recorded query of a candidate's own clip (mine = 0) against another agent's clip replays to its
// answer by brute force; held ground by the disks; the answers add up to the candidate's hits.
TEST(Crowd, RecordedQueriesReplayByBruteForce) {
    const CrowdRun c = run(wander(30, 15, 11));
    const Record& r = c.record;
    std::uint64_t replayed = 0, held = 0;
    for (std::size_t n = 0; n < r.choices.size(); ++n) {
        const ChoicePoint& cp = r.choices[n];
        const auto& own = r.tracks[std::size_t(cp.agent)].clips;
        const auto at =
            std::find_if(own.begin(), own.end(), [&](const PlacedClip& p) { return p.choice == std::int64_t(n); });
        ASSERT_NE(at, own.end());
        ASSERT_EQ(at->start, cp.frame);
        for (const Candidate& k : cp.candidates) {
            EXPECT_EQ(k.against.size(), std::size_t(k.queries));
            int hits = 0;
            for (const CandidateQuery& q : k.against) {
                hits += q.hit;
                ASSERT_NE(q.agent, cp.agent);
                if (q.mine != 0 || q.agent < 0) continue;
                if (q.piece >= 0) {
                    const std::optional<FramedClip> other = query_clip(r, q);
                    ASSERT_TRUE(other);
                    EXPECT_LT(q.choice, int(n)) << "only what was committed before";
                    EXPECT_EQ(collide_brute(path_of(k.clip), at->place, path_of(other->clip), other->place), q.hit)
                        << "choice " << n;
                    ++replayed;
                } else if (q.choice >= 0) {
                    const std::optional<HeldGround> held_ground = query_hold(r, q);
                    ASSERT_TRUE(held_ground);
                    const auto& [disk, from] = *held_ground;
                    bool hit = false;
                    const double cs = std::cos(at->place.theta), sn = std::sin(at->place.theta);
                    const Path& p = path_of(k.clip);
                    for (std::size_t i = 0; i < p.size(); ++i) {
                        if (cp.frame + std::int64_t(i) + 1 <= from) continue;
                        const Sample& s = p.samples[i];
                        const double x = at->place.x + cs * s.x - sn * s.y, y = at->place.y + sn * s.x + cs * s.y;
                        hit = hit || std::hypot(x - disk[0], y - disk[1]) < s.r + disk[2] - 1e-9;
                    }
                    if (hit) {
                        EXPECT_TRUE(q.hit) << "choice " << n;
                    }
                    ++held;
                }
            }
            EXPECT_EQ(hits, k.hits);
        }
    }
    EXPECT_GT(replayed, 100u);
    EXPECT_GT(held, 10u);
}

// A candidate is taken only when its whole plan was free; those tried before it were not.
TEST(Crowd, TakesTheFirstCandidateWithAFreePlan) {
    const CrowdRun c = run(wander(40, 20, 13));
    int taken = 0, skipped = 0, gave_way = 0;
    for (const ChoicePoint& cp : c.record.choices) {
        if (cp.outcome != "candidate") continue;
        ASSERT_FALSE(cp.candidates.empty());
        // The first candidate with a free plan, unless it passed an agent that waits (giving way): then
        // the first later one that did not, else that one (taken after the moving candidates).
        std::size_t t = 0;
        while (t < cp.candidates.size() && cp.candidates[t].clip != cp.taken) ++t;
        ASSERT_LT(t, cp.candidates.size());
        for (const CandidateQuery& q : cp.candidates[t].against) {
            // Routes tried before the one taken may have hit; the clip's own queries came first, all free.
            if (q.mine == 0) {
                EXPECT_FALSE(q.hit);
            }
        }
        EXPECT_TRUE(cp.holds) << "a taken candidate reserves where it would stop";
        ++taken;
        for (std::size_t k = 0; k < t; ++k) {
            const Candidate& x = cp.candidates[k];
            if (x.hits == 0 && !x.crowded) {  // free, and it gave way: tested in full
                EXPECT_GT(x.queries, 0);
                ++gave_way;
                continue;
            }
            ++skipped;
        }
    }
    EXPECT_GT(taken, 100);
    EXPECT_GT(skipped, 0);
    EXPECT_LT(gave_way, skipped / 10) << "giving way is rare: most candidates before the one taken are not free";
}

TEST(Crowd, RandomModeRunsEveryQuery) {
    CrowdOptions o = wander(30, 10, 1, Selection::Random);
    o.log_queries = true;
    const CrowdRun c = run(o, fixture().mobb);
    std::uint64_t per_candidate = 0;
    for (const ChoicePoint& cp : c.record.choices) {
        EXPECT_FALSE(cp.fallback);
        for (const Candidate& k : cp.candidates) per_candidate += std::uint64_t(k.queries);
    }
    EXPECT_EQ(per_candidate, c.summary.queries);
    EXPECT_EQ(c.queries.size(), c.summary.queries);
    EXPECT_FALSE(c.record.world.walls) << "the paper's timing workload has no walls";
    for (std::size_t k = 0; k < c.queries.size(); k += 7) {
        const LoggedQuery& q = c.queries[k];
        EXPECT_EQ(collide_brute(path_of(q.clip_a), q.pa, path_of(q.clip_b), q.pb), q.hit);
    }
}

TEST(Crowd, RecordRoundTripsThroughAFile) {
    CrowdOptions o = wander(8, 6, 9);
    o.world.obstacles.push_back(Polygon::rectangle(3, 4, 4, 6));
    const CrowdRun c = run(o);
    const std::string file = temp_file("crowd_record.json");
    {
        std::ofstream f(file);
        f << record_to_text(c.record, summary_json(c.summary));
    }
    const Record r = load_record(file);
    std::remove(file.c_str());
    ASSERT_EQ(r.tracks.size(), c.record.tracks.size());
    EXPECT_EQ(r.frames, c.record.frames);
    EXPECT_EQ(r.world.x1, o.world.x1);
    EXPECT_TRUE(r.world.walls);
    ASSERT_EQ(r.world.obstacles.size(), 1u);
    EXPECT_EQ(r.world.obstacles[0].vertices, o.world.obstacles[0].vertices);
    EXPECT_EQ(r.tracks[2].samples[17], c.record.tracks[2].samples[17]);
    EXPECT_EQ(r.choices.size(), c.record.choices.size());
    for (std::size_t k = 0; k < r.choices.size(); ++k) {
        const ChoicePoint &x = r.choices[k], &y = c.record.choices[k];
        EXPECT_EQ(x.outcome, y.outcome);
        EXPECT_EQ(x.escape.size(), y.escape.size());
        EXPECT_EQ(x.hold, y.hold);
        for (std::size_t j = 0; j < x.candidates.size(); ++j) {
            const auto &a = x.candidates[j].against, &b = y.candidates[j].against;
            ASSERT_EQ(a.size(), b.size());
            for (std::size_t q = 0; q < a.size(); ++q)
                EXPECT_TRUE(a[q].agent == b[q].agent && a[q].choice == b[q].choice && a[q].solid == b[q].solid &&
                            a[q].piece == b[q].piece && a[q].mine == b[q].mine && a[q].hit == b[q].hit);
        }
    }
    EXPECT_EQ(frame_contacts(r).size(), c.summary.contacts);
}

// The choice points of a frame run in parallel and are committed in agent order; any thread count
// gives the very same record, logged queries (in the same order) and counters.
TEST(Crowd, ThreadCountDoesNotChangeTheRun) {
    for (Selection select : {Selection::Wander, Selection::Random}) {
        // Dense enough that choice points of one frame often meet (re-evaluations).
        CrowdOptions o = wander(60, 15, 21, select);
        o.log_queries = true;
        const CrowdRun ref = run(o);
        const std::string text = record_to_text(ref.record, summary_json(ref.summary));
        const std::string log = logged_text(ref.queries);
        EXPECT_GT(ref.summary.reevaluated, 0u) << to_string(select);
        for (int threads : {2, 3, 8}) {
            o.threads = threads;
            const CrowdRun r = run(o);
            EXPECT_EQ(r.summary.threads, threads);
            EXPECT_TRUE(record_to_text(r.record, summary_json(r.summary)) == text)
                << to_string(select) << ", " << threads << " threads";
            EXPECT_TRUE(logged_text(r.queries) == log) << to_string(select) << ", " << threads << " threads";
            EXPECT_EQ(counters(r.summary), counters(ref.summary)) << to_string(select) << ", " << threads << " threads";
        }
    }
}

// Frames of 20 to 30 choice points: the current ones between two stale ones commit as runs on every
// thread (commit.cpp), and frames re-evaluate and reroute (the right of way) in a denser crowd. Records
// as on one thread.
TEST(Crowd, RunsCommittedInParallelKeepTheRecord) {
    CrowdOptions o = wander(900, 8, 4);
    o.world.x1 *= 0.6, o.world.y1 *= 0.6;  // 4.3 m^2 per agent: crowded
    const CrowdRun ref = run(o);
    const std::string text = record_to_text(ref.record, summary_json(ref.summary));
    EXPECT_GT(ref.summary.reevaluated, 100u);
    EXPECT_GT(ref.summary.right_of_way, 0u);
    // Steps handed to the workers: none on one thread, as many on any count from 2.
    EXPECT_EQ(ref.summary.parallel_steps, 0u);
    std::uint64_t steps = 0;
    for (int threads : {2, 3}) {
        o.threads = threads;
        const CrowdRun r = run(o);
        EXPECT_TRUE(record_to_text(r.record, summary_json(r.summary)) == text) << threads << " threads";
        EXPECT_EQ(counters(r.summary), counters(ref.summary)) << threads << " threads";
        if (threads == 2) steps = r.summary.parallel_steps;
        EXPECT_EQ(r.summary.parallel_steps, steps);
    }
    EXPECT_GT(steps, 0u);
}

// The record's text without what depends on when a choice point was evaluated: its `pruned`, the pieces
// live in the broad phase then that it skipped - a measure of the work, as the summary's counters are.
std::string behaviour_text(Record r, const std::string& summary) {
    for (ChoicePoint& c : r.choices) c.pruned = 0;
    return record_to_text(r, summary);
}

// A frame's choice points run as consecutive batches of at most max_batch (the first frame: every
// agent's), each committed before the next is evaluated: the agents do as in one batch, down to one
// choice point at a time - the order of evaluation the parallel frame stands for. Only the work differs:
// fewer re-evaluations, the smaller the batches.
TEST(Crowd, BatchSizeDoesNotChangeTheRun) {
    CrowdOptions crowded = wander(300, 4, 6);
    crowded.world.x1 *= 0.6, crowded.world.y1 *= 0.6;
    CrowdOptions goals =
        scenario_options(load_scenario(std::string(MOBB_SOURCE_DIR) + "/assets/scenarios/evacuation_exit.json"));
    goals.seconds = 8;
    for (CrowdOptions o : {crowded, goals}) {
        o.threads = 2;
        const CrowdRun ref = run(o);
        const std::string summary = summary_json(ref.summary);
        const std::string text = behaviour_text(ref.record, summary);
        EXPECT_GT(ref.summary.reevaluated, 5u) << to_string(o.select);
        for (int most : {1, 7}) {
            o.max_batch = most;
            const CrowdRun r = run(o);
            EXPECT_TRUE(behaviour_text(r.record, summary) == text) << to_string(o.select) << ", batches of " << most;
            EXPECT_EQ(r.summary.choice_points, ref.summary.choice_points);
            EXPECT_LT(r.summary.reevaluated, ref.summary.reevaluated) << to_string(o.select) << ", batches of " << most;
            if (most == 1) {
                EXPECT_EQ(r.summary.reevaluated, 0u);
            }
        }
    }
    CrowdOptions none = crowded;
    none.max_batch = 0;
    EXPECT_THROW(run(none), std::invalid_argument);
}

// More agents than random placement can fit (past its jamming limit) are refused before any is placed,
// saying about how many fit; as many as fit are placed.
TEST(Crowd, RandomStartsPastTheJammingLimitAreRefused) {
    CrowdOptions o = wander(2000, 1, 3);
    o.world.x1 = 40, o.world.y1 = 50;  // 1 m^2 an agent: disks on 73 % of the ground
    try {
        run(o);
        FAIL() << "2,000 agents placed on 2,000 m^2";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("placed at random, about 1"), std::string::npos) << e.what();
    }
    o.world.x1 = 60, o.world.y1 = 75;  // 2.25 m^2 an agent: 33 %
    EXPECT_EQ(run(o).record.tracks.size(), 2000u);
}

// Obstacles hold as the walls do: no sample disk of any agent overlaps one, checked here against the
// polygon's dense sampling (its interior on a fine grid and its edges).
TEST(Crowd, AgentsKeepClearOfObstacles) {
    CrowdOptions o = wander(30, 20, 17);
    o.world.obstacles = {Polygon::rectangle(5, 6, 6, 14), Polygon{{{12, 20}, {16, 22}, {13, 25}}}};
    const CrowdRun c = run(o);
    std::vector<std::array<double, 2>> dense;
    for (const Polygon& p : o.world.obstacles) {
        const auto b = bounds(p);
        for (double x = b[0]; x <= b[2]; x += 0.02)
            for (double y = b[1]; y <= b[3]; y += 0.02) {
                // Inside by the crossing count (the test's own).
                bool in = false;
                const auto& v = p.vertices;
                for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++)
                    if ((v[i][1] > y) != (v[j][1] > y) &&
                        x < (v[j][0] - v[i][0]) * (y - v[i][1]) / (v[j][1] - v[i][1]) + v[i][0])
                        in = !in;
                if (in) dense.push_back({x, y});
            }
    }
    int near = 0;
    for (const AgentTrack& t : c.record.tracks)
        for (const auto& s : t.samples)
            for (const auto& d : dense) {
                const double dist = std::hypot(s[1] - d[0], s[2] - d[1]);
                ASSERT_GE(dist, s[3] - 1e-9) << "a disk overlaps an obstacle at t = " << s[0];
                near += dist < s[3] + 0.5;
            }
    EXPECT_GT(near, 0) << "agents come near the obstacles";
    EXPECT_EQ(c.summary.contacts_unexcused, 0u);
}

// Whether a clip moves as the right of way counts it: its exit at least the idle speed away.
bool moves(int clip) {
    const GraphClip& c = fixture().graph.clips[std::size_t(clip)];
    return std::hypot(c.exit_x, c.exit_y) >= CrowdMetrics::kIdleSpeed * double(c.path.size()) * fixture().graph.dt();
}

// The first choice point of `agent` after choice point `n`, or nullptr.
const ChoicePoint* next_choice(const Record& r, std::size_t n, int agent) {
    for (std::size_t m = n + 1; m < r.choices.size(); ++m)
        if (r.choices[m].agent == agent) return &r.choices[m];
    return nullptr;
}

// Whether a candidate clip of choice point `cp` (placed where the clip taken there starts) meets held
// ground, by its samples.
bool meets_ground(const Record& r, const ChoicePoint& cp, int clip, const HeldGround& ground) {
    const auto& own = r.tracks[std::size_t(cp.agent)].clips;
    const auto at = std::find_if(own.begin(), own.end(), [&](const PlacedClip& p) { return p.start == cp.frame; });
    const double cs = std::cos(at->place.theta), sn = std::sin(at->place.theta);
    const Path& p = path_of(clip);
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (cp.frame + std::int64_t(i) + 1 <= ground.frame) continue;
        const Sample& s = p.samples[i];
        const double x = at->place.x + cs * s.x - sn * s.y, y = at->place.y + sn * s.x + cs * s.y;
        if (std::hypot(x - ground.disk[0], y - ground.disk[1]) < s.r + ground.disk[2] - 1e-9) return true;
    }
    return false;
}

// An agent that has not moved for 2 s may take a moving clip whose plan meets other agents' reservations
// once they found other ways to stop: those are reserved instead (later queries meet them, and replay by
// brute force), and nobody ever touches.
TEST(Crowd, RightOfWayReroutesTheOthersSafely) {
    int taken = 0, replayed = 0, crowded = 0;
    for (std::uint64_t seed = 1; seed <= 24; ++seed) {
        CrowdOptions o = wander(60, 30, seed);
        o.world.x1 = 20, o.world.y1 = 25;  // denser than the paper's: 8.3 m^2 per agent
        const CrowdRun c = run(o);
        const Record& r = c.record;
        EXPECT_TRUE(frame_contacts(r).empty()) << "seed " << seed;
        for (std::size_t n = 0; n < r.choices.size(); ++n) {
            const ChoicePoint& cp = r.choices[n];
            for (const Candidate& k : cp.candidates)
                for (const CandidateQuery& q : k.against) {
                    if (q.mine != 0 || q.agent < 0 || q.choice < 0) continue;
                    const ChoicePoint& holder = r.choices[std::size_t(q.choice)];
                    if (holder.outcome != "right of way" || q.agent == holder.agent) continue;
                    if (const auto other = query_clip(r, q)) {
                        const auto& own = r.tracks[std::size_t(cp.agent)].clips;
                        const auto at = std::find_if(own.begin(), own.end(),
                                                     [&](const PlacedClip& p) { return p.start == cp.frame; });
                        EXPECT_EQ(collide_brute(path_of(k.clip), at->place, path_of(other->clip), other->place), q.hit);
                    } else if (meets_ground(r, cp, k.clip, *query_hold(r, q))) {
                        EXPECT_TRUE(q.hit);
                    }
                    ++replayed;
                }
            if (cp.outcome != "right of way") continue;
            ++taken;
            EXPECT_TRUE(moves(cp.taken));
            std::int64_t waiting_since = 0;
            for (const PlacedClip& p : r.tracks[std::size_t(cp.agent)].clips)
                if (p.choice < std::int64_t(n) && moves(p.clip))
                    waiting_since = p.start + std::int64_t(path_of(p.clip).size());
            EXPECT_GE(double(cp.frame - waiting_since) * r.dt, 2.0 - 1e-9) << "choice " << n;
            if (cp.reroutes.empty()) {  // free but for the standing gap, which the right of way passes
                const auto k = std::find_if(cp.candidates.begin(), cp.candidates.end(),
                                            [&](const Candidate& x) { return x.clip == cp.taken; });
                ASSERT_NE(k, cp.candidates.end());
                EXPECT_TRUE(k->crowded) << "choice " << n;
                ++crowded;
                continue;
            }
            EXPECT_LE(cp.reroutes.size(), 2u);
            for (const ReroutedPlan& rr : cp.reroutes) {
                EXPECT_NE(rr.agent, cp.agent);
                if (rr.escape.empty()) continue;  // its clip's successor stands: it holds ground at once
                if (const ChoicePoint* next = next_choice(r, n, rr.agent)) {
                    EXPECT_EQ(next->frame, rr.escape[0].frame) << "the reroute starts where its clip ends";
                    if (next->outcome == "escape") {
                        EXPECT_EQ(next->taken, rr.escape[0].clip) << "it stops the new way";
                    }
                }
            }
        }
    }
    EXPECT_GE(taken, 5);
    EXPECT_GE(replayed, 5) << "later queries meet the rerouted plans";
    EXPECT_GE(crowded, 1) << "and some pass the standing gap";
}

// Where each agent waits at `frame`, as the crowd sees it then: agents whose last clip started before the
// frame ends 2 s or more after the end of their last clip that moves (else nullopt), at their held ground.
std::vector<std::optional<std::array<double, 2>>> waiting_at(const Record& r, std::int64_t frame) {
    std::vector<std::optional<std::array<double, 2>>> out(r.tracks.size());
    for (std::size_t w = 0; w < r.tracks.size(); ++w) {
        std::int64_t waiting_since = 0, end = 0;
        const PlacedClip* last = nullptr;
        for (const PlacedClip& p : r.tracks[w].clips) {
            if (p.start >= frame) break;
            last = &p;
            end = p.start + std::int64_t(path_of(p.clip).size());
            if (moves(p.clip)) waiting_since = end;
        }
        if (!last || double(end - waiting_since) * r.dt < 2.0 - 1e-9) continue;
        const ChoicePoint& own = r.choices[std::size_t(last->choice)];
        if (own.holds) out[w] = std::array<double, 2>{own.hold[0], own.hold[1]};
    }
    return out;
}

// Giving way: a free moving candidate passed over for a later one (or for none) passes within 2.5 m of
// an agent that waits; the one taken after it does not, unless no later moving candidate was free.
TEST(Crowd, GivesWayToThoseWhoWait) {
    int gave_way = 0, taken_anyway = 0;
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
        CrowdOptions o = wander(60, 30, seed);
        o.world.x1 = 20, o.world.y1 = 25;
        const CrowdRun c = run(o);
        const Record& r = c.record;
        EXPECT_TRUE(frame_contacts(r).empty()) << "seed " << seed;
        for (const ChoicePoint& cp : r.choices) {
            if (cp.outcome != "candidate") continue;
            std::size_t t = 0;
            while (t < cp.candidates.size() && cp.candidates[t].clip != cp.taken) ++t;
            ASSERT_LT(t, cp.candidates.size());
            const auto& own = r.tracks[std::size_t(cp.agent)].clips;
            const auto at =
                std::find_if(own.begin(), own.end(), [&](const PlacedClip& p) { return p.start == cp.frame; });
            ASSERT_NE(at, own.end());
            const auto waiting = waiting_at(r, cp.frame);
            const auto passes = [&](int clip) {
                const double cs = std::cos(at->place.theta), sn = std::sin(at->place.theta);
                for (const Sample& x : path_of(clip).samples)
                    for (std::size_t w = 0; w < waiting.size(); ++w) {
                        if (!waiting[w] || int(w) == cp.agent) continue;
                        const double px = at->place.x + cs * x.x - sn * x.y, py = at->place.y + sn * x.x + cs * x.y;
                        if (std::hypot(px - (*waiting[w])[0], py - (*waiting[w])[1]) < 2.5 - 1e-9) return true;
                    }
                return false;
            };
            bool skipped = false;
            for (std::size_t k = 0; k < t; ++k) {
                if (cp.candidates[k].hits > 0 || cp.candidates[k].crowded) continue;
                EXPECT_TRUE(moves(cp.candidates[k].clip));
                EXPECT_TRUE(passes(cp.candidates[k].clip)) << "agent " << cp.agent << " frame " << cp.frame;
                skipped = true;
                ++gave_way;
            }
            const std::size_t n = cp.candidates.size();
            if (skipped) {  // taken after those it passed over: the first free one clear of who waits
                EXPECT_EQ(t + 1, n);
                EXPECT_FALSE(passes(cp.taken));
            }
            if (t + 1 < n) {  // passed over and taken all the same: no later moving candidate was free and clear
                EXPECT_TRUE(passes(cp.taken));
                for (std::size_t k = t + 1; k < n; ++k) EXPECT_TRUE(moves(cp.candidates[k].clip));
                ++taken_anyway;
            }
        }
    }
    EXPECT_GE(gave_way, 5);
    EXPECT_GE(taken_anyway, 1);
}

// A wandering agent takes no candidate whose held ground comes within the standing gap of another
// agent's held ground, unless it already stood that close to it; those refused for that alone are
// marked "crowded" in the record.
TEST(Crowd, WanderersKeepRoomBetweenStandingPlaces) {
    int checked = 0, exempt = 0, crowded = 0;
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        CrowdOptions o = wander(60, 30, seed);
        o.world.x1 = 20, o.world.y1 = 25;
        const Record r = run(o).record;
        std::vector<std::optional<std::array<double, 3>>> held(r.tracks.size());  // each agent's, as committed
        for (const ChoicePoint& cp : r.choices) {
            for (const Candidate& k : cp.candidates) crowded += k.crowded ? 1 : 0;
            const auto& at = r.tracks[std::size_t(cp.agent)].samples[std::size_t(cp.frame)];  // where it stands
            for (std::size_t a = 0; cp.outcome == "candidate" && a < held.size(); ++a) {
                if (!held[a] || int(a) == cp.agent) continue;
                const auto& h = *held[a];
                const double room = cp.hold[2] + h[2] + CrowdTuning{}.standing_gap.width;
                if (std::hypot(at[1] - h[0], at[2] - h[1]) < room) {
                    ++exempt;
                    continue;
                }
                EXPECT_GE(std::hypot(cp.hold[0] - h[0], cp.hold[1] - h[1]), room - 1e-6)
                    << "seed " << seed << " agent " << cp.agent << " frame " << cp.frame;
                ++checked;
            }
            held[std::size_t(cp.agent)].reset();
            if (cp.holds) held[std::size_t(cp.agent)] = cp.hold;
            for (const ReroutedPlan& rr : cp.reroutes) held[std::size_t(rr.agent)] = rr.hold;
        }
    }
    EXPECT_GT(checked, 10000);
    EXPECT_GT(exempt, 0);
    EXPECT_GT(crowded, 20);
}

TEST(Crowd, RejectsImpossibleWorlds) {
    CrowdOptions o;
    o.agents = 1000;
    o.world.x1 = o.world.y1 = 5;
    EXPECT_THROW(run(o), std::invalid_argument);
    EXPECT_THROW(parse_selection("nearest"), std::invalid_argument);
    CrowdOptions none;
    none.threads = 0;
    EXPECT_THROW(run(none), std::invalid_argument);
    CrowdOptions walled;
    walled.placed = {{{0.1, 5, 0, 0}, 0, {}}};  // against the wall
    EXPECT_THROW(run(walled), std::invalid_argument);
    CrowdOptions close;
    close.placed = {{{5, 5, 0, 0}, 0, {}}, {{5.3, 5, 0, 0}, 0, {}}};
    EXPECT_THROW(run(close), std::invalid_argument);
}

}  // namespace
}  // namespace mobb::crowd
