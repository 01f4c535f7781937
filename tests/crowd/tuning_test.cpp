// CrowdTuning's fields by name (set_tuning, `mobb crowd --tune NAME=VALUE`): each by its name as the
// fields nest, and by the flat name of the release before, which sets the same field; bad names and
// values are errors naming them.
#include <gtest/gtest.h>

#include <functional>
#include <stdexcept>
#include <string>

#include "mobb/crowd/tuning.h"

namespace mobb::crowd {
namespace {

struct Named {
    const char* name;  // as the fields nest
    const char* flat;  // the release before's
    std::function<double(const CrowdTuning&)> get;
    const char* value;  // not the default
    double want;
};

// Every field: the value set by each of its names.
const Named kNamed[] = {
    {"moving_speed", "moving_speed", [](const CrowdTuning& t) { return t.moving_speed; }, "0.5", 0.5},
    {"escape.steps", "escape_steps", [](const CrowdTuning& t) { return t.escape.steps; }, "4", 4},
    {"escape.routes", "escape_routes", [](const CrowdTuning& t) { return t.escape.routes; }, "8", 8},
    {"escape.wall_margin", "wall_margin", [](const CrowdTuning& t) { return t.escape.wall_margin; }, "0.2", 0.2},
    {"stand_near_walls.on", "stand_near_walls", [](const CrowdTuning& t) { return t.stand_near_walls.on; }, "off", 0},
    {"leave_in_stride.on", "leave_in_stride", [](const CrowdTuning& t) { return t.leave_in_stride.on; }, "false", 0},
    {"right_of_way.on", "right_of_way", [](const CrowdTuning& t) { return t.right_of_way.on; }, "0", 0},
    {"right_of_way.after", "right_of_way_after", [](const CrowdTuning& t) { return t.right_of_way.after; }, "3", 3},
    {"right_of_way.max_rerouted", "max_yielding", [](const CrowdTuning& t) { return t.right_of_way.max_rerouted; }, "1",
     1},
    {"give_way.on", "give_way", [](const CrowdTuning& t) { return t.give_way.on; }, "off", 0},
    {"give_way.after", "give_way_after", [](const CrowdTuning& t) { return t.give_way.after; }, "1.5", 1.5},
    {"give_way.reach", "give_way_reach", [](const CrowdTuning& t) { return t.give_way.reach; }, "3", 3},
    {"standing_gap.on", "standing_gap", [](const CrowdTuning& t) { return t.standing_gap.on; }, "off", 0},
    {"standing_gap.width", "standing_gap_width", [](const CrowdTuning& t) { return t.standing_gap.width; }, "0.3", 0.3},
    {"look_ahead.on", "look_ahead", [](const CrowdTuning& t) { return t.look_ahead.on; }, "off", 0},
    {"look_ahead.budget", "look_ahead_budget", [](const CrowdTuning& t) { return t.look_ahead.budget; }, "192", 192},
    {"look_ahead.dead_end", "look_ahead_dead_end", [](const CrowdTuning& t) { return t.look_ahead.dead_end; }, "1", 1},
    {"look_ahead.weight", "look_ahead.weight", [](const CrowdTuning& t) { return t.look_ahead.weight; }, "1", 1},
    {"look_ahead.learns", "look_ahead_learns", [](const CrowdTuning& t) { return t.look_ahead.learns; }, "off", 0},
    {"follow.on", "follow", [](const CrowdTuning& t) { return t.follow.on; }, "off", 0},
    {"follow.angle", "follow_angle", [](const CrowdTuning& t) { return t.follow.angle; }, "0.5", 0.5},
    {"follow.goal_reach", "follow_goal_reach", [](const CrowdTuning& t) { return t.follow.goal_reach; }, "2", 2},
    {"goal.walking", "goal_walking", [](const CrowdTuning& t) { return t.goal.walking; }, "1.1", 1.1},
    {"goal.turning", "goal_turning", [](const CrowdTuning& t) { return t.goal.turning; }, "1.4", 1.4},
    {"goal.personal", "goal_personal", [](const CrowdTuning& t) { return t.goal.personal; }, "1.5", 1.5},
    {"goal.crowding", "goal_crowding", [](const CrowdTuning& t) { return t.goal.crowding; }, "0.4", 0.4},
    {"goal.patience", "goal_patience", [](const CrowdTuning& t) { return t.goal.patience; }, "5", 5},
    {"goal.horizon", "goal_horizon", [](const CrowdTuning& t) { return t.goal.horizon; }, "2", 2},
    {"goal.nav_clearance", "nav_clearance", [](const CrowdTuning& t) { return t.goal.nav_clearance; }, "0.5", 0.5},
    {"goal.neighbourhood", "goal.neighbourhood", [](const CrowdTuning& t) { return t.goal.neighbourhood; }, "5", 5},
    {"goal.neighbours_ahead", "goal.neighbours_ahead", [](const CrowdTuning& t) { return t.goal.neighbours_ahead; },
     "3", 3},
    {"wander.open_ahead", "wander.open_ahead", [](const CrowdTuning& t) { return t.wander.open_ahead; }, "6", 6},
    {"wander.band", "wander.band", [](const CrowdTuning& t) { return t.wander.band; }, "0.5", 0.5},
};

TEST(Tuning, EachFieldIsSetByItsNameAndByItsFlatName) {
    for (const Named& n : kNamed) {
        const double before = n.get(CrowdTuning{});
        ASSERT_NE(before, n.want) << n.name << ": the test's value is the default";
        CrowdTuning nested, flat;
        set_tuning(nested, std::string(n.name) + "=" + n.value);
        set_tuning(flat, std::string(n.flat) + "=" + n.value);
        EXPECT_EQ(n.get(nested), n.want) << n.name;
        EXPECT_EQ(n.get(flat), n.want) << n.flat;
        // No other field moved: every other one keeps its default.
        for (const Named& m : kNamed) {
            if (m.name == n.name) continue;
            EXPECT_EQ(m.get(nested), m.get(CrowdTuning{})) << n.name << " moved " << m.name;
        }
    }
}

// The message of set_tuning's error for `assignment`.
std::string error_of(const std::string& assignment) {
    CrowdTuning t;
    try {
        set_tuning(t, assignment);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}

TEST(Tuning, BadNamesAndValuesAreErrorsNamingThem) {
    EXPECT_EQ(error_of("give_way.reach=far"), "give_way.reach: 'far' is not a finite number");
    EXPECT_EQ(error_of("give_way_reach=nan"), "give_way_reach: 'nan' is not a finite number");
    EXPECT_EQ(error_of("look_ahead.budget=1.5"), "look_ahead.budget: '1.5' is not an integer");
    EXPECT_EQ(error_of("follow.on=maybe"), "follow.on: 'maybe' is not true or false");
    EXPECT_EQ(error_of("give_way"), "give_way: no value (NAME=VALUE)");
    const std::string unknown = error_of("give_way.width=1");
    EXPECT_EQ(unknown.rfind("'give_way.width' is not a field of CrowdTuning (moving_speed, ", 0), 0u) << unknown;
    EXPECT_NE(unknown.find("give_way.reach"), std::string::npos) << unknown;
    EXPECT_EQ(error_of("give_way=on"), "");
}

}  // namespace
}  // namespace mobb::crowd
