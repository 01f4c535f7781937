// Leaving in stride (src/crowd/rules/leave_in_stride.h) called alone on a state built by hand
// (rule_scene.h): a clip ending within the goal radius of an exit is the whole plan, at a choice point too.
#include <gtest/gtest.h>

#include <array>

#include "choice/choice.h"
#include "rule_scene.h"
#include "rules/leave_in_stride.h"

namespace mobb::crowd {
namespace {

using namespace rule_test;  // Scene and the clips it places (rule_scene.h)

TEST(RuleUnits, LeavingInStrideTakesAClipEndingWithinTheGoalRadiusOfAnExit) {
    Scene scene;
    const int walk = walks(scene.g).front();
    const Placement base{0, 0, 0, 0};
    const PlacedCandidate c = candidate(scene, walk, base);
    const std::array<double, 2> end = clip_end(scene.g, walk, base);
    const double radius = scene.options.goal_radius;
    Agent a;
    a.goals = {{end[0] + 0.9 * radius, end[1]}};
    a.at_goal = AtGoal::Leave;
    const LeaveInStrideTuning on, off{false};
    EXPECT_TRUE(leaves_in_stride(on, scene.g, a, c, radius));
    EXPECT_FALSE(leaves_in_stride(off, scene.g, a, c, radius)) << "the rule off";
    EXPECT_FALSE(leaves_in_stride(on, scene.g, a, c, 0.8 * radius)) << "the clip ends outside the goal radius";
    Agent stays = a;
    stays.at_goal = AtGoal::Stay;
    EXPECT_FALSE(leaves_in_stride(on, scene.g, stays, c, radius)) << "its last goal is no exit";
    Agent on_the_way = a;
    on_the_way.goals.push_back({15, 15});
    EXPECT_FALSE(leaves_in_stride(on, scene.g, on_the_way, c, radius)) << "the exit is not its last goal";
    on_the_way.next_goal = 1;
    on_the_way.goals.back() = a.goals.front();
    EXPECT_TRUE(leaves_in_stride(on, scene.g, on_the_way, c, radius)) << "heading for its last goal, an exit";
}

// A goal agent 1.5 m short of its exit takes a clip into it, and reserves nothing beyond it with the rule
// on; off, its plan holds ground, as every plan does.
TEST(RuleUnits, LeavingInStrideLeavesThePlanEmptyAtTheChoicePoint) {
    for (const bool on : {true, false}) {
        Scene scene(Selection::Goal, {}, {{1.5, 0}});
        scene.options.tuning.leave_in_stride.on = on;
        const int a = scene.add_agent({0, 0, 0, 0});
        scene.agents[std::size_t(a)].goals = {{1.5, 0}};
        scene.agents[std::size_t(a)].at_goal = AtGoal::Leave;
        scene.stand(a);
        Choice choice;
        choice.prepare(scene.state(), a, 0);
        choice.evaluate(scene.state());
        const BoxedClip& taken = choice.taken();
        ASSERT_EQ(choice.outcome(), Outcome::Candidate);
        const bool leaves = reaches_goal(clip_end(scene.g, taken.clip, taken.place), {1.5, 0}, 1.0);
        EXPECT_TRUE(leaves) << "the clip taken ends in the exit";
        EXPECT_EQ(!choice.plan().hold && choice.plan().escape.empty(), on && leaves);
    }
}

}  // namespace
}  // namespace mobb::crowd
