// Each crowd rule on a situation built for it, with the rule on and switched off (CrowdTuning): the
// look-ahead gets an agent out of a ring of standing agents through its gap; the right of way, giving way
// and the standing gap act in a dense wandering crowd, and leave no trace when off (each on a small
// situation of its own: rule_situations_test.cpp); the policies decide what is theirs (whether choices reserve anything, who keeps the standing gap, who stops near walls).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "committed_graph.h"
#include "mobb/crowd/metrics/metrics.h"
#include "mobb/crowd/sim/crowd.h"
#include "plan/escape.h"

namespace mobb::crowd {
namespace {

const MotionGraph& graph() { return test::committed_graph(); }

CrowdRun run(const CrowdOptions& o) { return run_crowd(graph(), NarrowPhase::sweep(graph()), o); }

// An agent at the centre of a ring of nine standing agents 2.6 m away, packed too close to pass between
// (1.36 m apart, centre to centre), with a gap behind it; its goal is 8 m ahead, beyond the ring's
// closed side: the way out goes away from the goal first.
CrowdOptions ring(std::uint64_t seed, bool look_ahead) {
    CrowdOptions o;
    o.world = {-10, -10, 10, 10, true, {}};
    o.select = Selection::Goal;
    o.seconds = 40;
    o.seed = seed;
    o.tuning.look_ahead.on = look_ahead;
    AgentSpec centre;
    centre.start = {0, 0, 0, 0};
    centre.goals = {{8, 0}};
    o.placed.push_back(centre);
    for (int k = 0; k < 12; ++k) {
        const double a = 2 * M_PI * k / 12;
        if (std::abs(std::remainder(a - M_PI, 2 * M_PI)) < 0.6) continue;  // the gap, at -x
        AgentSpec standing;
        standing.start = {2.6 * std::cos(a), 2.6 * std::sin(a), a, 0};
        standing.goals = {{standing.start.x, standing.start.y}};  // at its goal from the start
        o.placed.push_back(standing);
    }
    o.agents = int(o.placed.size());
    return o;
}

// The frame the centre agent first comes within 1 m of its goal, or the run's length.
std::int64_t centre_arrival(const Record& r) {
    const auto& s = r.tracks[0].samples;
    for (std::size_t f = 0; f < s.size(); ++f)
        if (std::hypot(s[f][1] - 8, s[f][2]) < 1.0) return std::int64_t(f);
    return r.frames;
}

TEST(Rules, LookAheadLeavesARingThroughItsGapSooner) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        const CrowdRun with = run(ring(seed, true));
        const CrowdRun without = run(ring(seed, false));
        EXPECT_EQ(with.record.tracks.size(), 10u);
        const std::int64_t a = centre_arrival(with.record), b = centre_arrival(without.record);
        EXPECT_LT(a, with.record.frames) << "seed " << seed << ": out of the ring and at its goal";
        EXPECT_LT(a, b) << "seed " << seed << ": sooner than trying the candidates in the policy's order";
        EXPECT_TRUE(frame_contacts(with.record).empty());
        EXPECT_TRUE(crowd_metrics(with.record, graph()).passed);
        // The intended clips are there with the look-ahead, and only then.
        bool intended = false;
        for (const ChoicePoint& c : with.record.choices) intended = intended || !c.intended.empty();
        EXPECT_TRUE(intended);
        for (const ChoicePoint& c : without.record.choices) EXPECT_TRUE(c.intended.empty());
    }
}

// Learned times to go switched off (CrowdTuning::look_ahead_learns): the search alone still takes the
// agent out of the ring and to its goal, without contact, and the runs differ - the switch acts and is
// safe. Which is sooner depends on the seed here (bench/results/log.md, "Goal crowds that look ahead").
TEST(Rules, LookAheadLearningSwitchesOff) {
    bool differs = false;
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        CrowdOptions o = ring(seed, true);
        const CrowdRun with = run(o);
        o.tuning.look_ahead.learns = false;
        const CrowdRun without = run(o);
        EXPECT_TRUE(frame_contacts(without.record).empty()) << "seed " << seed;
        EXPECT_LT(centre_arrival(without.record), without.record.frames) << "seed " << seed;
        differs = differs || centre_arrival(with.record) != centre_arrival(without.record);
    }
    EXPECT_TRUE(differs);
}

// 60 wanderers in 20 x 25 m (8.3 m^2 each, denser than the paper's), 30 s: every rule acts in it.
CrowdOptions dense(std::uint64_t seed) {
    CrowdOptions o;
    o.agents = 60;
    o.world = {0, 0, 20, 25, true, {}};
    o.seconds = 30;
    o.seed = seed;
    return o;
}

TEST(Rules, RightOfWayActsAndSwitchesOff) {
    std::uint64_t taken = 0;  // rare: a few in a handful of seeds
    for (std::uint64_t seed = 1; seed <= 8; ++seed) {
        CrowdOptions o = dense(seed);
        const CrowdRun on = run(o);
        o.tuning.right_of_way.on = false;
        const CrowdRun off = run(o);
        taken += on.summary.right_of_way;
        EXPECT_EQ(off.summary.right_of_way, 0u);
        EXPECT_EQ(off.summary.reroutes, 0u);
        for (const ChoicePoint& c : off.record.choices) EXPECT_NE(c.outcome, "right of way");
        EXPECT_TRUE(frame_contacts(on.record).empty());
        EXPECT_TRUE(frame_contacts(off.record).empty());
    }
    EXPECT_GT(taken, 0u);
}

// Passed over: a free candidate (no hit, not refused for the standing gap) tried before the one taken.
int passed_over(const Record& r) {
    int n = 0;
    for (const ChoicePoint& c : r.choices) {
        if (c.outcome != "candidate") continue;
        for (std::size_t k = 0; k + 1 < c.candidates.size(); ++k)
            if (c.candidates[k].hits == 0 && !c.candidates[k].crowded) ++n;
    }
    return n;
}

TEST(Rules, GivingWayReordersAndSwitchesOff) {
    CrowdOptions o = dense(1);
    const CrowdRun on = run(o);
    o.tuning.give_way.on = false;
    const CrowdRun off = run(o);
    EXPECT_GE(passed_over(on.record), 5) << "free walks passed over for one clear of those who wait";
    EXPECT_EQ(passed_over(off.record), 0) << "off: the first free candidate is taken";
    EXPECT_TRUE(frame_contacts(off.record).empty());
}

int crowded(const Record& r) {
    int n = 0;
    for (const ChoicePoint& c : r.choices)
        for (const Candidate& k : c.candidates) n += k.crowded ? 1 : 0;
    return n;
}

TEST(Rules, StandingGapIsTheWanderersAndSwitchesOff) {
    CrowdOptions o = dense(1);
    const CrowdRun on = run(o);
    o.tuning.standing_gap.on = false;
    const CrowdRun off = run(o);
    EXPECT_GT(crowded(on.record), 5);
    EXPECT_EQ(crowded(off.record), 0);
    EXPECT_TRUE(frame_contacts(off.record).empty());
    // Goal agents converge on purpose: their policy keeps no gap, whatever the switch says.
    const CrowdRun goal = run(ring(1, true));
    EXPECT_EQ(crowded(goal.record), 0);
}

// A policy of the given kind in an empty default world, no goals.
std::unique_ptr<Policy> policy(Selection kind) {
    static const std::vector<char> in_place(graph().clips.size(), 0);
    static const World world;
    return make_policy(kind, {graph(), world, in_place, {}, 1.0, {}});
}

TEST(Rules, EachPolicySaysWhatIsItsOwn) {
    EXPECT_FALSE(policy(Selection::Random)->avoids());
    EXPECT_TRUE(policy(Selection::Wander)->avoids());
    EXPECT_TRUE(policy(Selection::Wander)->keeps_standing_gap());
    EXPECT_FALSE(policy(Selection::Random)->keeps_standing_gap());
    // The random policy's crowd reserves nothing: no escapes, no walls.
    CrowdOptions o = dense(1);
    o.select = Selection::Random;
    o.seconds = 5;
    const CrowdRun r = run(o);
    EXPECT_FALSE(r.record.world.walls);
    EXPECT_EQ(r.summary.escapes, 0u);
    for (const ChoicePoint& c : r.record.choices) EXPECT_FALSE(c.holds);
}

// Stopping near walls (CrowdTuning::stand_near_walls) is the goal agents': wanderers' held ground keeps
// room to turn from the walls, so one that stops facing a wall can still turn and walk away.
TEST(Rules, OnlyGoalAgentsStopNearWalls) {
    EXPECT_FALSE(policy(Selection::Wander)->stops_near_walls());
    EXPECT_TRUE(policy(Selection::Goal)->stops_near_walls());
    const EscapeTable table = EscapeTable::build(graph());
    const CrowdOptions o = dense(1);
    const CrowdRun r = run(o);
    const std::vector<Polygon> solids = o.world.solids();
    int holds = 0;
    for (const ChoicePoint& c : r.record.choices) {
        if (!c.holds) continue;
        ++holds;
        for (const Polygon& p : solids)
            ASSERT_FALSE(disk_overlaps(p, c.hold[0], c.hold[1], table.turn_clearance * (1 - 1e-6)))
                << "agent " << c.agent << " frame " << c.frame;
    }
    EXPECT_GT(holds, 1000);
}

}  // namespace
}  // namespace mobb::crowd
