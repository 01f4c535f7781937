// Following (src/crowd/rules/follow.h) called alone on a state built by hand (rule_scene.h): whom an
// agent follows, and which of a leader's pieces it plans past.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "rule_scene.h"
#include "rules/follow.h"

namespace mobb::crowd {
namespace {

using namespace rule_test;  // Scene and the clips it places (rule_scene.h)

// Agent `a` walks `walk` from `at` at frame 0 and reserves its first escape route: its pieces' ids, the
// clip first, then the escape clips and the held ground.
std::vector<int> walk_on(Scene& scene, int a, int walk, const Placement& at) {
    const BoxedClip c = scene.play(a, walk, at, 0);
    scene.reserve(a, plan_along(scene.state(), c, scene.escapes.routes[std::size_t(walk)].front()));
    std::vector<int> ids{int(scene.pieces.size()) - 1 - int(scene.agents[std::size_t(a)].reserved.size())};
    for (int id : scene.agents[std::size_t(a)].reserved) ids.push_back(id);
    return ids;
}

TEST(RuleUnits, FollowingTrustsTheReservationsOfALeaderAheadGoingTheSameWay) {
    Scene scene;
    const FollowTuning t;
    const int walk = walks(scene.g).front();
    scene.add_agent({0, 0, 0, 0});  // the one asking, at `from`
    const int ahead = scene.add_agent({2, 0, 0, 0}), facing_me = scene.add_agent({4, 3, M_PI, 0}),
              behind = scene.add_agent({-8, 0, 0, 0});
    const std::vector<int> leader = walk_on(scene, ahead, walk, {2, 0, 0, 0});
    const std::vector<int> oncoming = walk_on(scene, facing_me, walk, {4, 3, M_PI, 0});
    const std::vector<int> follower = walk_on(scene, behind, walk, {-8, 0, 0, 0});
    const CrowdState s = scene.state();
    const std::array<double, 2> from{0, 0};
    ASSERT_GE(leader.size(), 2u);
    EXPECT_FALSE(walks_on(t, s, 0, from, s.pieces[std::size_t(leader[0])])) << "the clip it plays is certain";
    for (std::size_t i = 1; i < leader.size(); ++i)
        EXPECT_TRUE(walks_on(t, s, 0, from, s.pieces[std::size_t(leader[i])])) << "its reservation " << i;
    for (std::size_t i = 1; i < oncoming.size(); ++i)
        EXPECT_FALSE(walks_on(t, s, 0, from, s.pieces[std::size_t(oncoming[i])])) << "it faces the other way";
    for (std::size_t i = 1; i < follower.size(); ++i)
        EXPECT_FALSE(walks_on(t, s, 0, from, s.pieces[std::size_t(follower[i])])) << "it is behind";
    // Wanting to go north, the one ahead to the east is no leader.
    const Piece& held = s.pieces[std::size_t(leader.back())];
    EXPECT_FALSE(walks_on(t, s, M_PI / 2, from, held));
    // Its held ground 0.5 rad off the way east: followed within the cone of 0.8 rad, not within 0.3.
    const SpaceTimeBox b = box_of(held);
    const std::array<double, 2> aside{0.5 * (b.x0 + b.x1) - 3, 0.5 * (b.y0 + b.y1) - 3 * std::tan(0.5)};
    ASSERT_LT(std::abs(*leader_facing(t, s, ahead)), 0.3) << "it walks east";
    EXPECT_TRUE(walks_on(t, s, 0, aside, held));
    EXPECT_FALSE(walks_on({true, 0.3, 3.0}, s, 0, aside, held));
}

TEST(RuleUnits, FollowingHasNoLeaderThatIsAboutToStopForGood) {
    Scene scene;
    const FollowTuning t;
    const int walk = walks(scene.g).front();
    const int a = scene.add_agent({0, 0, 0.3, 0});
    const CrowdState s = scene.state();
    EXPECT_FALSE(leader_facing(t, s, a)) << "it has not set off";
    scene.play(a, walk, {0, 0, 0.3, 0}, 0);
    const Placement end = scene.g.next({0, 0, 0.3, 0}, walk);
    ASSERT_TRUE(leader_facing(t, s, a));
    EXPECT_EQ(*leader_facing(t, s, a), end.theta);
    Agent& agent = scene.agents[std::size_t(a)];
    agent.goals = {{end.x + 0.9 * t.goal_reach, end.y}};  // where it stays, its clip ending near
    EXPECT_FALSE(leader_facing(t, s, a)) << "about to stand at its goal";
    agent.at_goal = AtGoal::Leave;
    EXPECT_TRUE(leader_facing(t, s, a)) << "it leaves there: it walks on";
    agent.at_goal = AtGoal::Stay;
    agent.goals = {{end.x + 1.1 * t.goal_reach, end.y}};
    EXPECT_TRUE(leader_facing(t, s, a)) << "farther from its goal";
    agent.arrived = true;
    EXPECT_FALSE(leader_facing(t, s, a)) << "stopped for good";
}

}  // namespace
}  // namespace mobb::crowd
