// Taking one's escape (src/crowd/rules/take_escape.h) called alone on a state built by hand
// (rule_scene.h): the next clip of the plan reserved, else an idle clip inside the held ground.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "rule_scene.h"
#include "rules/take_escape.h"

namespace mobb::crowd {
namespace {

using namespace rule_test;  // Scene and the clips it places (rule_scene.h)

// The first clip of `kind` of the graph.
int first_of(const MotionGraph& g, ClipKind kind) {
    for (int c = 0; c < int(g.clips.size()); ++c)
        if (kind_of(g.clips[std::size_t(c)], c) == kind) return c;
    return -1;
}

TEST(RuleUnits, FollowingTheEscapePlaysTheNextClipOfThePlanReserved) {
    Scene scene;
    const int a = scene.add_agent({0, 0, 0, 0});
    const BoxedClip walk = scene.play(a, walks(scene.g).front(), {0, 0, 0, 0}, 0);
    const auto& routes = scene.escapes.routes[std::size_t(walk.clip)];
    const auto route = std::find_if(routes.begin(), routes.end(), [](const auto& r) { return r.size() >= 3; });
    ASSERT_NE(route, routes.end()) << "a route of two stopping clips, then the idle one";
    const Plan plan = plan_along(scene.state(), walk, *route);
    ASSERT_EQ(plan.escape.size(), route->size() - 1);
    scene.reserve(a, plan);
    const ChoiceBase base{a, walk.frame + std::int64_t(scene.g.clips[std::size_t(walk.clip)].path.size()), {}, {}};
    BoxedClip clip;
    Plan rest;
    ASSERT_TRUE(take_escape(scene.state(), base, clip, rest));
    EXPECT_EQ(clip.clip, plan.escape[0].clip);
    EXPECT_EQ(clip.frame, plan.escape[0].frame);
    ASSERT_EQ(rest.escape.size(), plan.escape.size() - 1);
    EXPECT_EQ(rest.escape[0].clip, plan.escape[1].clip);
    ASSERT_TRUE(rest.hold);
    EXPECT_EQ(rest.hold->x, plan.hold->x);
    EXPECT_EQ(rest.hold->frame, plan.hold->frame);
}

TEST(RuleUnits, FollowingTheEscapeStandsOnInsideTheHeldGround) {
    Scene scene;
    const Placement at{3, 4, 0.5, 0};
    const int a = scene.add_agent(at);
    const int idle = first_of(scene.g, ClipKind::Idle);
    ASSERT_GE(idle, 0);
    scene.play(a, idle, at, 0);
    scene.stand(a);
    const std::int64_t frame = std::int64_t(scene.g.clips[std::size_t(idle)].path.size());
    Placement base = scene.g.next(at, idle);
    base.t0 = double(frame) * scene.g.dt();
    BoxedClip clip;
    Plan plan;
    ASSERT_TRUE(take_escape(scene.state(), {a, frame, base, Rigid2::of(base)}, clip, plan));
    // An idle successor of the clip played, every disk inside the held ground, which it keeps.
    const Hold& h = *scene.agents[std::size_t(a)].plan.hold;
    EXPECT_EQ(scene.escapes.kind[std::size_t(clip.clip)], ClipKind::Idle);
    const auto& next = scene.g.clips[std::size_t(idle)].successors;
    EXPECT_NE(std::find(next.begin(), next.end(), clip.clip), next.end());
    EXPECT_EQ(clip.frame, frame);
    const Rigid2 m = Rigid2::of(base);
    for (const Sample& x : scene.g.clips[std::size_t(clip.clip)].path.samples)
        EXPECT_LE(std::hypot(m.apply_x(x.x, x.y) - h.x, m.apply_y(x.x, x.y) - h.y) + x.r, h.r * (1 + 1e-9));
    EXPECT_TRUE(plan.escape.empty());
    ASSERT_TRUE(plan.hold);
    EXPECT_EQ(plan.hold->x, h.x);
    EXPECT_EQ(plan.hold->r, h.r);
    // Held ground too small for any idle clip, away from its centre: no escape left.
    scene.agents[std::size_t(a)].plan.hold->r = 0.01;
    base.x += 0.05;
    EXPECT_FALSE(take_escape(scene.state(), {a, frame, base, Rigid2::of(base)}, clip, plan));
    scene.agents[std::size_t(a)].plan.hold.reset();
    EXPECT_FALSE(take_escape(scene.state(), {a, frame, base, Rigid2::of(base)}, clip, plan)) << "no ground held";
}

}  // namespace
}  // namespace mobb::crowd
