// The standing gap (src/crowd/rules/standing_gap.h) called alone on a state built by hand (rule_scene.h):
// exactly the routes whose held ground comes within the gap of another's, and only for wanderers.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "plan/choice_queries.h"
#include "rule_scene.h"
#include "rules/standing_gap.h"

namespace mobb::crowd {
namespace {

using namespace rule_test;  // Scene and the clips it places (rule_scene.h)

// Where candidate `clip` placed at `base` would hold ground along each of its escape routes.
std::vector<Hold> route_holds(const Scene& scene, int clip, const ChoiceBase& base) {
    std::vector<Hold> out;
    const auto& routes = scene.escapes.routes[std::size_t(clip)];
    const BoxedClip c = frame_clip(scene.state(), clip, base.place, base.m, base.frame);
    for (const std::vector<int>& route : routes) out.push_back(*plan_along(scene.state(), c, route).hold);
    return out;
}

// The routes (bits) whose held ground comes within `gap` of `other`: what the rule must find.
std::uint32_t within_gap(const std::vector<Hold>& holds, const Hold& other, double gap) {
    std::uint32_t bits = 0;
    for (std::size_t r = 0; r < holds.size(); ++r)
        if (holds_meet(holds[r], other, gap)) bits |= 1u << r;
    return bits;
}

TEST(RuleUnits, StandingGapMarksExactlyTheRoutesStoppingWithinTheGapOfAnother) {
    Scene scene;
    const StandingGapTuning gap;
    const int walk = walks(scene.g).front();
    const Placement at{0, 0, 0, 0};
    const ChoiceBase base{scene.add_agent(at), 0, at, Rigid2::of(at)};
    scene.stand(base.agent);
    const std::vector<Hold> holds = route_holds(scene, walk, base);
    ASSERT_GE(holds.size(), 2u);
    // Another agent standing just within the gap of one route's held ground, on the side where some of
    // the other routes' stay clear of it.
    const double r = scene.escapes.hold_radius;
    const std::uint32_t all = (1u << holds.size()) - 1;
    Hold other{0, 0, r, 0};
    std::uint32_t want = 0;
    for (std::size_t k = 0; k < holds.size() && (want == 0 || want == all); ++k)
        for (int turn = 0; turn < 16 && (want == 0 || want == all); ++turn) {
            const double a = 2 * M_PI * turn / 16, d = holds[k].r + r + 0.5 * gap.width;
            other = {holds[k].x + d * std::cos(a), holds[k].y + d * std::sin(a), r, 0};
            want = holds_meet(other, {at.x, at.y, r, 0}, gap.width) ? 0 : within_gap(holds, other, gap.width);
        }
    ASSERT_TRUE(want != 0 && want != all) << "a place within the gap of some routes' held ground only";
    const int b = scene.add_agent({other.x, other.y, 0, 0});
    scene.stand(b);
    ChoiceQueries q;
    q.start(base.agent, 0);
    EXPECT_EQ(crowded_routes(gap, scene.state(), base, walk, q), want);
    EXPECT_EQ(q.queried(), 1) << "one query, noted";
    EXPECT_EQ(crowded_routes({false}, scene.state(), base, walk, q), 0u) << "the rule off";
    // One standing that close to the agent already is left out: it could not stop otherwise.
    const Placement near{other.x, other.y, 0, 0};
    const ChoiceBase close{base.agent, 0, near, Rigid2::of(near)};
    EXPECT_EQ(crowded_routes(gap, scene.state(), close, walk, q), 0u);
}

TEST(RuleUnits, StandingGapIsKeptByWanderersOnly) {
    Scene scene(Selection::Goal, {}, {{10, 0}});
    const int walk = walks(scene.g).front();
    const Placement at{0, 0, 0, 0};
    const ChoiceBase base{scene.add_agent(at), 0, at, Rigid2::of(at)};
    const std::vector<Hold> holds = route_holds(scene, walk, base);
    const int b = scene.add_agent({holds[0].x, holds[0].y, 0, 0});
    scene.stand(b);
    ChoiceQueries q;
    q.start(base.agent, 0);
    EXPECT_EQ(crowded_routes({}, scene.state(), base, walk, q), 0u) << "goal agents converge on purpose";
}

}  // namespace
}  // namespace mobb::crowd
