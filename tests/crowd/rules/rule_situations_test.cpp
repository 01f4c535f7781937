// Crowd rules, each on a small situation built by hand in which it must act, run with the rule on
// and switched off (CrowdTuning), besides the dense wandering crowd of rules_test.cpp:
// - the standing gap: a wanderer in a corridor closed by an agent standing still - it turns back, again
//   and again, and reserves no ground within the gap of the standing agent's;
// - giving way: a walker passing an agent boxed in by four walls (so it waits) takes, where it has one, a
//   free walk clear of the waiting agent instead of the first free one, which passes by it;
// - the right of way: an agent in a niche off a corridor, kept in by a column of walkers, takes its way
//   out through a walker's reserved stop once it has waited, and that walker stops another way;
// - following: a column of goal agents in front of a door waits in line behind the one ahead and goes
//   through, rather than walking round a queue that has no way round;
// - stopping near walls: the same column holds ground inside the door's turning room, never its standing
//   room;
// - leaving in stride: two columns converging on one exit hold no stop beyond it, and are out sooner;
// - letting through: of two agents crossing a door from either side, the one farther from it keeps out of
//   the way of the one nearer, which comes through first, and both are through sooner;
// - keeping right: two columns meeting head-on in a corridor pass in lanes on every seed, where without
//   it some seeds stand face to face.
// Each is the smallest situation found in which the rule must act - a few agents placed by hand, walls
// where the rule needs the others kept out - and asserts what the rule is for; with the rule off, what it
// prevents happens, and neither run has a contact. Wanderers' choices depend on the seed: several each.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "committed_graph.h"
#include "mobb/crowd/metrics/metrics.h"
#include "mobb/crowd/sim/crowd.h"
#include "plan/escape.h"

namespace mobb::crowd {
namespace {

const MotionGraph& graph() { return test::committed_graph(); }

CrowdRun run(const CrowdOptions& o) { return run_crowd(graph(), NarrowPhase::sweep(graph()), o); }

AgentSpec agent(double x, double y, double heading, double start_time = 0) {
    AgentSpec a;
    a.start = {x, y, heading, 0};
    a.start_time = start_time;
    return a;
}

// Whether a clip moves (EscapeTable::moves: what the rules count as not waiting).
bool moves(int clip) {
    static const EscapeTable table = EscapeTable::build(graph());
    return table.moves[std::size_t(clip)];
}

// The frame agent `a` first starts a clip that moves (the run's length if never).
std::int64_t first_move(const Record& r, int a) {
    for (const PlacedClip& c : r.tracks[std::size_t(a)].clips)
        if (moves(c.clip)) return c.start;
    return r.frames;
}

// Where agent `a` is at `frame` (its track), metres.
std::array<double, 2> at(const Record& r, int a, std::int64_t frame) {
    const auto& s = r.tracks[std::size_t(a)].samples[std::size_t(frame)];
    return {s[1], s[2]};
}

double distance(const std::array<double, 2>& p, const std::array<double, 2>& q) {
    return std::hypot(p[0] - q[0], p[1] - q[1]);
}

// ---- The standing gap ----

// A corridor 2.4 m wide, too narrow to pass the agent standing in it (start_time beyond the run: it holds
// its start to the end); a wanderer 3 m away walks toward it.
CrowdOptions closed_corridor(std::uint64_t seed, bool standing_gap) {
    CrowdOptions o;
    o.world = {-5, -1.2, 2, 1.2, true, {}};
    o.seconds = 20;
    o.seed = seed;
    o.tuning.standing_gap.on = standing_gap;
    o.placed = {agent(0, 0, 0, 1000), agent(-3, 0, 0)};
    o.agents = 2;
    return o;
}

// The held ground agent `a` reserved (ChoicePoint::hold, taken candidates) within `zone` of `p`, from
// choice points where it stood outside that zone (inside it the rule leaves the test out: it could not
// stop otherwise).
int holds_into(const Record& r, int a, const std::array<double, 2>& p, double zone) {
    int n = 0;
    for (const ChoicePoint& c : r.choices) {
        if (c.agent != a || !c.holds || c.outcome != "candidate") continue;
        if (distance(at(r, a, c.frame), p) < zone) continue;
        if (distance({c.hold[0], c.hold[1]}, p) < zone) ++n;
    }
    return n;
}

int crowded(const Record& r, int a) {
    int n = 0;
    for (const ChoicePoint& c : r.choices)
        if (c.agent == a)
            for (const Candidate& k : c.candidates) n += k.crowded ? 1 : 0;
    return n;
}

// The nearest agent `a` comes to `p` while playing a clip that does not move (standing, turning on the
// spot, creeping).
double nearest_standing(const Record& r, int a, const std::array<double, 2>& p) {
    const AgentTrack& t = r.tracks[std::size_t(a)];
    double best = 1e300;
    for (const PlacedClip& c : t.clips) {
        if (moves(c.clip)) continue;
        const auto end = std::min<std::int64_t>(c.start + std::int64_t(graph().clips[std::size_t(c.clip)].path.size()),
                                                std::int64_t(t.samples.size()));
        for (std::int64_t f = c.start; f < end; ++f) best = std::min(best, distance(at(r, a, f), p));
    }
    return best;
}

TEST(RuleSituations, StandingGapKeepsAWandererFromStoppingByOneWhoStands) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        const CrowdRun on = run(closed_corridor(seed, true));
        const CrowdRun off = run(closed_corridor(seed, false));
        const std::array<double, 2> standing = at(on.record, 0, 0);
        // Held disks closer than the gap beyond touching: both radii (the record's) and the gap.
        const double zone = 2 * on.record.choices.front().hold[2] + CrowdTuning{}.standing_gap.width;
        EXPECT_GT(crowded(on.record, 1), 0) << "seed " << seed << ": candidates refused for the gap";
        EXPECT_EQ(holds_into(on.record, 1, standing, zone), 0) << "seed " << seed;
        EXPECT_EQ(crowded(off.record, 1), 0) << "seed " << seed;
        EXPECT_GT(holds_into(off.record, 1, standing, zone), 0) << "seed " << seed << ": off, it plans to stop close";
        // Where it actually stands still: farther from the standing agent with the gap.
        EXPECT_GT(nearest_standing(on.record, 1, standing), nearest_standing(off.record, 1, standing))
            << "seed " << seed;
        EXPECT_EQ(first_move(on.record, 0), on.record.frames) << "it stands throughout";
        EXPECT_TRUE(frame_contacts(on.record).empty()) << "seed " << seed;
        EXPECT_TRUE(frame_contacts(off.record).empty()) << "seed " << seed;
    }
}

// ---- Giving way ----

std::vector<Polygon> box_around(double x, double y, double half, double t) {
    return {Polygon::rectangle(x - half - t, y - half - t, x - half, y + half + t),
            Polygon::rectangle(x + half, y - half - t, x + half + t, y + half + t),
            Polygon::rectangle(x - half, y - half - t, x + half, y - half),
            Polygon::rectangle(x - half, y + half, x + half, y + half + t)};
}

// An agent boxed in by four walls (1 m from it: room to turn on the spot, none to walk), so it waits
// from its second clip on; a wanderer 5 m away heading to pass it about 2 m off, within give_way_reach.
CrowdOptions boxed_in(std::uint64_t seed, bool give_way) {
    CrowdOptions o;
    o.world = {-15, -15, 15, 15, true, box_around(0, 0, 1.0, 0.2)};
    o.seconds = 10;
    o.seed = seed;
    o.tuning.give_way.on = give_way;
    o.placed = {agent(0, 0, 0), agent(-5, 2.7, -0.2)};
    o.agents = 2;
    return o;
}

// The nearest clip `clip` placed at `p` comes to `q` (its root samples, as giving way measures it).
double clip_nearest(int clip, const Placement& p, const std::array<double, 2>& q) {
    const Rigid2 m = Rigid2::of(p);
    double best = 1e300;
    for (const Sample& s : graph().clips[std::size_t(clip)].path.samples)
        best = std::min(best, distance({m.apply_x(s.x, s.y), m.apply_y(s.x, s.y)}, q));
    return best;
}

const ChoicePoint* nth_choice(const Record& r, int a, std::size_t n) {
    for (const ChoicePoint& c : r.choices)
        if (c.agent == a && n-- == 0) return &c;
    return nullptr;
}

const PlacedClip& clip_at(const Record& r, int a, std::int64_t frame) {
    for (const PlacedClip& c : r.tracks[std::size_t(a)].clips)
        if (c.start == frame) return c;
    throw std::logic_error("no clip starts there");
}

// Where the agent waits as the others see it at `frame`: the ground its last plan before the frame holds.
std::array<double, 2> waiting_at(const Record& r, int a, std::int64_t frame) {
    std::array<double, 2> p{};
    for (const ChoicePoint& c : r.choices)
        if (c.agent == a && c.frame < frame) p = {c.hold[0], c.hold[1]};
    return p;
}

TEST(RuleSituations, GivingWayTakesAWalkClearOfAnAgentThatWaits) {
    const double reach = CrowdTuning{}.give_way.reach;
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
        const CrowdRun on = run(boxed_in(seed, true));
        const CrowdRun off = run(boxed_in(seed, false));
        EXPECT_TRUE(frame_contacts(on.record).empty()) << "seed " << seed;
        EXPECT_TRUE(frame_contacts(off.record).empty()) << "seed " << seed;
        EXPECT_EQ(first_move(on.record, 0), on.record.frames) << "the boxed agent never moves: it waits";
        // The same runs up to the walker's first choice point where the rule acted.
        const ChoicePoint *a = nullptr, *b = nullptr;
        for (std::size_t n = 0;; ++n) {
            a = nth_choice(on.record, 1, n), b = nth_choice(off.record, 1, n);
            if (!a || !b || a->taken != b->taken) break;
        }
        ASSERT_TRUE(a && b) << "seed " << seed << ": the walker chose otherwise once";
        ASSERT_EQ(a->frame, b->frame);
        const Placement base = clip_at(off.record, 1, b->frame).place;
        const std::array<double, 2> waits = waiting_at(on.record, 0, a->frame);
        // Off: the first free walk, passing the waiting agent; on: that one passed over for one clear of it.
        EXPECT_LT(clip_nearest(b->taken, base, waits), reach) << "seed " << seed;
        EXPECT_GE(clip_nearest(a->taken, base, waits), reach) << "seed " << seed;
        const auto is = [](int clip) { return [clip](const Candidate& k) { return k.clip == clip; }; };
        const auto passed = std::find_if(a->candidates.begin(), a->candidates.end(), is(b->taken));
        const auto taken = std::find_if(a->candidates.begin(), a->candidates.end(), is(a->taken));
        EXPECT_TRUE(passed < taken && taken != a->candidates.end()) << "seed " << seed;
    }
}

// ---- The right of way ----

// A niche 2 m wide off a corridor 2.3 m wide, an agent in it facing out; five wanderers in a column 2.5 m
// apart walk along the corridor past its mouth, the first standing in it at the start. All wander
// (walks come first in their order, so the agent in the niche tries its way out at every choice point).
CrowdOptions niche(std::uint64_t seed, bool right_of_way) {
    CrowdOptions o;
    o.world = {-12, -1, 12, 2.5, true, {Polygon::rectangle(-12, -1, -1, 0.2), Polygon::rectangle(1, -1, 12, 0.2)}};
    o.seconds = 12;
    o.seed = seed;
    o.tuning.right_of_way.on = right_of_way;
    o.placed = {agent(0, 0, M_PI / 2)};
    for (int k = 0; k < 5; ++k) o.placed.push_back(agent(-2.5 * k, 1.3, 0));
    o.agents = int(o.placed.size());
    return o;
}

TEST(RuleSituations, RightOfWayReroutesTheOneBlockingAWaitingAgent) {
    const std::int64_t after = std::llround(CrowdTuning{}.right_of_way.after / graph().dt());
    std::int64_t sooner = 0;
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
        const CrowdRun on = run(niche(seed, true));
        const CrowdRun off = run(niche(seed, false));
        EXPECT_TRUE(frame_contacts(on.record).empty()) << "seed " << seed;
        EXPECT_TRUE(frame_contacts(off.record).empty()) << "seed " << seed;
        EXPECT_EQ(off.summary.right_of_way, 0u);
        EXPECT_EQ(off.summary.reroutes, 0u);
        const std::int64_t a = first_move(on.record, 0), b = first_move(off.record, 0);
        EXPECT_LE(a, b) << "seed " << seed;
        if (a == b) continue;
        ++sooner;
        // Out sooner: by the right of way, after waiting, through a walker's reserved stop, which gave way.
        const auto c = std::find_if(on.record.choices.begin(), on.record.choices.end(),
                                    [&](const ChoicePoint& p) { return p.agent == 0 && p.frame == a; });
        ASSERT_NE(c, on.record.choices.end());
        EXPECT_EQ(c->outcome, "right of way") << "seed " << seed;
        EXPECT_GE(a, after) << "seed " << seed;
        ASSERT_EQ(c->reroutes.size(), 1u) << "seed " << seed;
        EXPECT_NE(c->reroutes[0].agent, 0);
    }
    EXPECT_GE(sooner, 3) << "out of the niche sooner in most seeds";
}

// ---- Following ----

// A wall across the world with a 2.4 m door; five goal agents in a column 1.5 m apart in front of it,
// facing it, for an exit 6 m beyond, where each leaves the run.
CrowdOptions door_column(std::uint64_t seed, bool follow) {
    CrowdOptions o;
    o.world = {-8, -4, 10, 4, true, {Polygon::rectangle(-0.5, -4, 0.5, -1.2), Polygon::rectangle(-0.5, 1.2, 0.5, 4)}};
    o.seconds = 60;
    o.seed = seed;
    o.select = Selection::Goal;
    o.tuning.follow.on = follow;
    for (int k = 0; k < 5; ++k) {
        AgentSpec a = agent(2.0 + 1.5 * k, 0, M_PI);
        a.goals = {{-6, 0}};
        a.at_goal = AtGoal::Leave;
        o.placed.push_back(a);
    }
    o.agents = int(o.placed.size());
    return o;
}

// The door column of five with stopping near walls on or off (and following on).
CrowdOptions door_column_near_walls(std::uint64_t seed, bool stand_near_walls) {
    CrowdOptions o = door_column(seed, true);
    o.tuning.stand_near_walls.on = stand_near_walls;
    return o;
}

// Whether a choice point's held ground comes within `room` metres of a wall or an obstacle of `o`.
bool holds_within(const Record& r, const CrowdOptions& o, double room) {
    for (const ChoicePoint& c : r.choices)
        for (const Polygon& p : o.world.solids())
            if (disk_overlaps(p, c.hold[0], c.hold[1], room)) return true;
    return false;
}

// Clips agent `a` played standing in place (turning on the spot, idle) before it left.
int in_place_clips(const Record& r, int a) {
    static const EscapeTable table = EscapeTable::build(graph());
    int n = 0;
    for (const PlacedClip& c : r.tracks[std::size_t(a)].clips) n += table.in_place[std::size_t(c.clip)] ? 1 : 0;
    return n;
}

TEST(RuleSituations, FollowingKeepsAColumnInLineThroughADoor) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        const CrowdRun on = run(door_column(seed, true));
        const CrowdRun off = run(door_column(seed, false));
        EXPECT_TRUE(frame_contacts(on.record).empty()) << "seed " << seed;
        EXPECT_TRUE(frame_contacts(off.record).empty()) << "seed " << seed;
        const CrowdMetrics m_on = crowd_metrics(on.record, graph()), m_off = crowd_metrics(off.record, graph());
        ASSERT_EQ(m_on.reached, 5) << "seed " << seed;
        ASSERT_EQ(m_off.reached, 5) << "seed " << seed;
        // Off, the agents behind turn on the spot and walk round a queue that has no way round; on, they
        // wait behind the one ahead and are through sooner.
        EXPECT_LT(m_on.mean_time_to_goal, m_off.mean_time_to_goal) << "seed " << seed;
        int turns_on = 0, turns_off = 0;
        for (int a = 1; a < 5; ++a)
            turns_on += in_place_clips(on.record, a), turns_off += in_place_clips(off.record, a);
        EXPECT_LT(turns_on, turns_off) << "seed " << seed;
    }
}

// ---- Stopping near walls ----

TEST(RuleSituations, StandingNearWallsStopsInsideTheDoorsTurningRoom) {
    const EscapeTable table = EscapeTable::build(graph());
    const double stand = table.stand_clearance, turn = table.turn_clearance;
    ASSERT_LT(stand, turn);
    int nearer = 0;
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        const CrowdOptions o_on = door_column_near_walls(seed, true), o_off = door_column_near_walls(seed, false);
        const CrowdRun r_on = run(o_on), r_off = run(o_off);
        EXPECT_TRUE(frame_contacts(r_on.record).empty()) << "seed " << seed;
        EXPECT_TRUE(frame_contacts(r_off.record).empty()) << "seed " << seed;
        EXPECT_EQ(crowd_metrics(r_on.record, graph()).reached, 5) << "seed " << seed;
        // Held ground never within room to stand; off, never within room to turn; on, it uses the door.
        EXPECT_FALSE(holds_within(r_on.record, o_on, stand * (1 - 1e-6))) << "seed " << seed;
        EXPECT_FALSE(holds_within(r_off.record, o_off, turn * (1 - 1e-6))) << "seed " << seed;
        nearer += holds_within(r_on.record, o_on, turn) ? 1 : 0;
    }
    EXPECT_GE(nearer, 2) << "agents stop within turning room of the door's posts in most seeds";
}

// ---- Leaving in stride ----

// Ten goal agents in two columns 3 m apart, 1.5 m between agents, in the open, for one exit between the
// columns 5 m beyond their heads, where each leaves the run.
CrowdOptions exit_columns(std::uint64_t seed, bool leave_in_stride) {
    CrowdOptions o;
    o.world = {-10, -4, 10, 4, true, {}};
    o.seconds = 40;
    o.seed = seed;
    o.select = Selection::Goal;
    o.tuning.leave_in_stride.on = leave_in_stride;
    for (int k = 0; k < 10; ++k) {
        AgentSpec a = agent(2.0 + 1.5 * (k / 2), k % 2 ? 1.5 : -1.5, M_PI);
        a.goals = {{-3, 0}};
        a.at_goal = AtGoal::Leave;
        o.placed.push_back(a);
    }
    o.agents = int(o.placed.size());
    return o;
}

// The last choice point of agent `a` before it left: the one whose clip took it to the exit.
const ChoicePoint& last_choice(const Record& r, int a) {
    const auto c =
        std::find_if(r.choices.rbegin(), r.choices.rend(), [&](const ChoicePoint& p) { return p.agent == a; });
    if (c == r.choices.rend()) throw std::logic_error("no choice point");
    return *c;
}

TEST(RuleSituations, LeavingInStrideReservesNoStopBeyondTheExit) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        const CrowdRun on = run(exit_columns(seed, true));
        const CrowdRun off = run(exit_columns(seed, false));
        EXPECT_TRUE(frame_contacts(on.record).empty()) << "seed " << seed;
        EXPECT_TRUE(frame_contacts(off.record).empty()) << "seed " << seed;
        for (int a = 0; a < 10; ++a) {
            ASSERT_TRUE(on.record.tracks[std::size_t(a)].left_frame) << "seed " << seed << " agent " << a;
            ASSERT_TRUE(off.record.tracks[std::size_t(a)].left_frame) << "seed " << seed << " agent " << a;
            // On, the clip into the exit is the whole plan; off, a stop beyond it is held until the agent left.
            EXPECT_FALSE(last_choice(on.record, a).holds) << "seed " << seed << " agent " << a;
            EXPECT_TRUE(last_choice(off.record, a).holds) << "seed " << seed << " agent " << a;
        }
        const CrowdMetrics m_on = crowd_metrics(on.record, graph()), m_off = crowd_metrics(off.record, graph());
        // Off, each waits at the exit for the stop the one before holds there until it has left.
        EXPECT_LT(m_on.mean_time_to_goal, m_off.mean_time_to_goal) << "seed " << seed;
    }
}

// ---- Letting through ----

// A corridor cut by a wall with a 1.6 m door (SteerSuite's doorway-two-way, the east agent nearer the
// door): two goal agents cross it from either side, each to the far end. Facing along walls is off: on
// its own it clears this door as fast as letting through on seeds 2 and 3, which would hide the rule.
CrowdOptions door_two_way(std::uint64_t seed, bool let_through) {
    CrowdOptions o;
    o.world = {-16, -1, 16, 3.1, true, {Polygon::rectangle(-0.2, -1, 0, -0.3), Polygon::rectangle(-0.2, 1.3, 0, 3.1)}};
    o.seconds = 60;
    o.seed = seed;
    o.select = Selection::Goal;
    o.tuning.let_through.on = let_through;
    o.tuning.face_along_walls.on = false;
    AgentSpec west = agent(-10, 1, 0), east = agent(7, 1, M_PI);
    west.goals = {{14, 1}};
    east.goals = {{-14, 1}};
    o.placed = {west, east};
    o.agents = 2;
    return o;
}

// The frame agent `a` first crosses x = 0 (the door); the run's length if never.
std::int64_t crosses_door(const Record& r, int a) {
    const auto& samples = r.tracks[std::size_t(a)].samples;
    for (std::size_t f = 1; f < samples.size(); ++f)
        if ((samples[f - 1][1] < 0) != (samples[f][1] < 0)) return std::int64_t(f);
    return r.frames;
}

TEST(RuleSituations, LettingThroughClearsADoorForTheOneNearerIt) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        const CrowdRun on = run(door_two_way(seed, true));
        const CrowdRun off = run(door_two_way(seed, false));
        EXPECT_TRUE(frame_contacts(on.record).empty()) << "seed " << seed;
        EXPECT_TRUE(frame_contacts(off.record).empty()) << "seed " << seed;
        const CrowdMetrics m_on = crowd_metrics(on.record, graph()), m_off = crowd_metrics(off.record, graph());
        ASSERT_EQ(m_on.reached, 2) << "seed " << seed;
        ASSERT_EQ(m_off.reached, 2) << "seed " << seed;
        // On, the west agent keeps out of the lane of the east one, which is nearer the door: it comes
        // through first, and neither waits face to face with the other.
        EXPECT_LT(crosses_door(on.record, 1), crosses_door(on.record, 0)) << "seed " << seed;
        EXPECT_LT(m_on.mean_time_to_goal, m_off.mean_time_to_goal) << "seed " << seed;
    }
}

// ---- Keeping right ----

// A corridor 4.6 m wide: two columns of eight goal agents, 1.4 m apart on its middle line, walk at each
// other from 16 m apart, each agent to an exit at the far end.
CrowdOptions columns_meeting(std::uint64_t seed, bool keep_right) {
    CrowdOptions o;
    o.world = {-20, -2.3, 20, 2.3, true, {}};
    o.seconds = 80;
    o.seed = seed;
    o.select = Selection::Goal;
    o.tuning.keep_right.on = keep_right;
    for (int k = 0; k < 8; ++k) {
        AgentSpec east = agent(-8 - 1.4 * k, 0, 0), west = agent(8 + 1.4 * k, 0, M_PI);
        east.goals.push_back({19, 0});
        west.goals.push_back({-19, 0});
        east.at_goal = west.at_goal = AtGoal::Leave;
        o.placed.push_back(east);
        o.placed.push_back(west);
    }
    o.agents = int(o.placed.size());
    return o;
}

// The mean time to goal of a run, or the run's length when an agent never got there.
double mean_time_or_jam(const CrowdRun& r, const CrowdOptions& o) {
    const CrowdMetrics m = crowd_metrics(r.record, graph());
    return m.reached == o.agents ? m.mean_time_to_goal : o.seconds;
}

TEST(RuleSituations, KeepingRightTakesTheJamsOutOfTwoColumnsMeeting) {
    double worst_on = 0, worst_off = 0;
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
        const CrowdOptions o_on = columns_meeting(seed, true), o_off = columns_meeting(seed, false);
        const CrowdRun on = run(o_on), off = run(o_off);
        EXPECT_TRUE(frame_contacts(on.record).empty()) << "seed " << seed;
        EXPECT_TRUE(frame_contacts(off.record).empty()) << "seed " << seed;
        EXPECT_EQ(crowd_metrics(on.record, graph()).reached, 16) << "seed " << seed;
        worst_on = std::max(worst_on, mean_time_or_jam(on, o_on));
        worst_off = std::max(worst_off, mean_time_or_jam(off, o_off));
    }
    // Off, the columns meet across the whole width and some seeds stand face to face for half a minute or
    // more; on, they pass in lanes every time (where they would have flowed anyway, somewhat slower:
    // bench/results/log.md, "Keeping right in corridors").
    EXPECT_LT(worst_on, 0.75 * worst_off);
}

}  // namespace
}  // namespace mobb::crowd
