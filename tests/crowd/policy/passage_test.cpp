// Passages (PassageMap): a door in a wall is one and the ground before it measures its distance from
// the door around the wall; a room's own walls, open ground and a wide gap are none; a narrow gap
// between two obstacles is one.
#include <gtest/gtest.h>

#include "policy/passage.h"

namespace mobb::crowd {
namespace {

constexpr double kCell = 0.25;

// A walled 20 x 12 m room cut at x = 10 by a wall 0.5 m thick with a door of `door` metres at y = 6.
World room_with_door(double door) {
    World world{0, 0, 20, 12, true, {}};
    world.obstacles.push_back(Polygon::rectangle(10, 0, 10.5, 6 - door / 2));
    world.obstacles.push_back(Polygon::rectangle(10, 6 + door / 2, 10.5, 12));
    return world;
}

TEST(PassageMap, ADoorIsAPassageAndTheGroundBeforeItIsMeasuredFromIt) {
    const PassageMap map(room_with_door(2.0), 3.0, 4.0, kCell);
    ASSERT_TRUE(map.any());
    EXPECT_EQ(map.distance(10.25, 6.1), 0) << "in the door";
    // Straight before the door, about as far as one stands from it (within a cell's diagonal).
    EXPECT_NEAR(map.distance(8, 6.1), 2.0, 0.4);
    EXPECT_NEAR(map.distance(12.5, 6.1), 2.0, 0.4);
    // Beside the door along the wall, nearer than straight out; far off, the reach.
    EXPECT_LT(map.distance(9.5, 9), 4.0);
    EXPECT_EQ(map.distance(3, 3), 4.0);
    EXPECT_EQ(map.distance(-1, 6), 4.0) << "outside the world";
}

TEST(PassageMap, AWideDoorARoomsWallsAndOpenGroundAreNone) {
    EXPECT_FALSE(PassageMap(room_with_door(3.5), 3.0, 4.0, kCell).any()) << "a door wider than narrow";
    EXPECT_FALSE(PassageMap(World{0, 0, 20, 12, true, {}}, 3.0, 4.0, kCell).any()) << "a room's own walls";
    World open{0, 0, 20, 12, false, {}};
    open.obstacles.push_back(Polygon::rectangle(9, 5, 11, 7));
    EXPECT_FALSE(PassageMap(open, 3.0, 4.0, kCell).any()) << "an obstacle in open ground";
}

TEST(PassageMap, ANarrowGapBetweenObstaclesIsAPassage) {
    World open{0, 0, 20, 12, false, {}};
    open.obstacles.push_back(Polygon::rectangle(5, 5, 9, 7));
    open.obstacles.push_back(Polygon::rectangle(11, 5, 15, 7));  // a 2 m gap between them
    const PassageMap map(open, 3.0, 4.0, kCell);
    ASSERT_TRUE(map.any());
    EXPECT_EQ(map.distance(10.1, 6.1), 0);
    EXPECT_GT(map.distance(10.1, 9.5), 2.0) << "2.5 m out of the gap, beyond the obstacles' ends";
}

}  // namespace
}  // namespace mobb::crowd
