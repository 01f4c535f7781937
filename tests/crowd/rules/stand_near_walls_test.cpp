// Stopping near walls (src/crowd/rules/stand_near_walls.h) called alone: room to stand for goal agents'
// held ground, room to turn otherwise.
#include <gtest/gtest.h>

#include <vector>

#include "rule_scene.h"
#include "rules/stand_near_walls.h"

namespace mobb::crowd {
namespace {

using namespace rule_test;  // Scene and the clips it places (rule_scene.h)

// A goal agent may hold ground in a door 1.6 m wide with the rule on (room to stand), not with it off
// (room to turn), and a wanderer never: meets_solid with the clearance the rule gives.
TEST(RuleUnits, StandingNearWallsLetsGoalAgentsStopWithRoomToStand) {
    const std::vector<Polygon> door{Polygon::rectangle(-0.5, -4, 0.5, -0.8), Polygon::rectangle(-0.5, 0.8, 0.5, 4)};
    Scene goal(Selection::Goal, door, {{5, 0}}), wander(Selection::Wander, door);
    const EscapeTable& e = goal.escapes;
    ASSERT_LT(e.stand_clearance, 0.8);
    ASSERT_GT(e.turn_clearance, 0.8);
    EXPECT_EQ(hold_clearance({}, *goal.policy, e), e.stand_clearance);
    EXPECT_EQ(hold_clearance({false}, *goal.policy, e), e.turn_clearance);
    EXPECT_EQ(hold_clearance({}, *wander.policy, e), e.turn_clearance) << "wanderers keep room to turn";
    Piece in_door;
    in_door.kind = Piece::Held;
    in_door.hold = {0, 0, e.hold_radius, 0};
    const auto meets_a_post = [&](Scene& scene, double clearance) {
        scene.hold_clearance = clearance;
        bool meets = false;
        for (int k = 0; k < int(scene.solids.size()); ++k) meets = meets || meets_solid(scene.state(), in_door, k);
        return meets;
    };
    EXPECT_FALSE(meets_a_post(goal, hold_clearance({}, *goal.policy, e)));
    EXPECT_TRUE(meets_a_post(goal, hold_clearance({false}, *goal.policy, e)));
    EXPECT_TRUE(meets_a_post(wander, hold_clearance({}, *wander.policy, e)));
}

}  // namespace
}  // namespace mobb::crowd
