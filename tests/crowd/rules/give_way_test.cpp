// Giving way (src/crowd/rules/give_way.h) called alone on a state built by hand (rule_scene.h): who
// waits, the walks that pass one, and a free walk that passes one deferred at a choice point for a later
// walk clear of it.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "choice/choice.h"
#include "rule_scene.h"
#include "rules/give_way.h"

namespace mobb::crowd {
namespace {

using namespace rule_test;  // Scene and the clips it places (rule_scene.h)

// Agent `a` waits on the ground it holds, as Simulation::apply_waiting marks it.
void wait(Scene& scene, int a) {
    const Hold& h = *scene.agents[std::size_t(a)].plan.hold;
    scene.waiting_at[std::size_t(a)] = {h.x, h.y};
    scene.waiting.insert(a, a, waiting_ground(scene.options.tuning.give_way, h));
}

// The nearest the root samples of clip `clip` placed at `p` come to `q` (giving way's measure).
double nearest(const MotionGraph& g, int clip, const Placement& p, const std::array<double, 2>& q) {
    const Rigid2 m = Rigid2::of(p);
    double best = 1e300;
    for (const Sample& x : g.clips[std::size_t(clip)].path.samples)
        best = std::min(best, std::hypot(m.apply_x(x.x, x.y) - q[0], m.apply_y(x.x, x.y) - q[1]));
    return best;
}

TEST(RuleUnits, GivingWayFindsTheWalksPassingAnAgentThatWaits) {
    Scene scene;
    const GiveWayTuning t;
    const int walk = walks(scene.g).front();
    const Placement at{0, 0, 0, 0};
    const ChoiceBase base{scene.add_agent(at), 0, at, Rigid2::of(at)};
    const PlacedCandidate c = candidate(scene, walk, at);
    const std::array<double, 2> mid = clip_end(scene.g, walk, {0.5 * c.place.x, 0, 0, 0});
    int passing = 0, clear = 0;
    std::vector<int> scratch;
    for (const double side : {1.0, 2.0, 2.4, 2.6, 3.0, 4.0}) {
        Scene s2;
        s2.add_agent(at);
        const int w = s2.add_agent({mid[0] * 0.5, side, 0, 0});
        s2.stand(w);
        wait(s2, w);
        const bool passes = nearest(s2.g, walk, at, s2.waiting_at[std::size_t(w)]) < t.reach;
        EXPECT_EQ(passes_waiting(t, s2.state(), base, c, scratch), passes) << side;
        EXPECT_FALSE(passes_waiting({false}, s2.state(), base, c, scratch)) << "the rule off";
        (passes ? passing : clear)++;
    }
    EXPECT_GT(passing, 0);
    EXPECT_GT(clear, 0);
    // The agent's own waiting is none of its concern.
    scene.stand(base.agent);
    wait(scene, base.agent);
    EXPECT_FALSE(passes_waiting(t, scene.state(), base, c, scratch));
}

TEST(RuleUnits, GivingWayCountsAsWaitingOneThatHasNotMovedForAWhile) {
    const GiveWayTuning t;
    const double dt = mobb::test::committed_graph().dt();
    Agent a;
    a.plan.hold = Hold{0, 0, 0.4, 0};
    a.waiting_since = 100;
    const auto after = std::int64_t(std::ceil(t.after / dt));
    EXPECT_TRUE(waits(t, a, 100 + after, dt, true));
    EXPECT_FALSE(waits(t, a, 100 + after - 1, dt, true)) << "not yet";
    EXPECT_FALSE(waits({false}, a, 100 + after, dt, true)) << "the rule off";
    EXPECT_FALSE(waits(t, a, 100 + after, dt, false)) << "a policy that does not avoid";
    Agent arrived = a;
    arrived.arrived = true;
    EXPECT_FALSE(waits(t, arrived, 100 + after, dt, true)) << "at its goal for good";
    Agent walking = a;
    walking.plan.hold.reset();
    EXPECT_FALSE(waits(t, walking, 100 + after, dt, true)) << "no ground held";
    const SpaceTimeBox b = waiting_ground(t, *a.plan.hold);
    EXPECT_EQ(b.x1 - b.x0, 2 * t.reach);
    EXPECT_EQ(b.f0, std::numeric_limits<std::int64_t>::min());
}

// A choice point of a wanderer at the origin, with giving way `on`, beside an agent that waits at `waiter`
// (none when null), evaluated: the scene and the choice.
std::pair<std::unique_ptr<Scene>, std::unique_ptr<Choice>> wanderer(bool on, const std::array<double, 2>* waiter) {
    auto scene = std::make_unique<Scene>();
    scene->options.tuning.give_way.on = on;
    const int a = scene->add_agent({0, 0, 0, 0});
    scene->stand(a);
    if (waiter) {
        const int w = scene->add_agent({(*waiter)[0], (*waiter)[1], 0, 0});
        scene->stand(w);
        wait(*scene, w);
    }
    auto choice = std::make_unique<Choice>();
    choice->prepare(scene->state(), a, 0);
    choice->evaluate(scene->state());
    return {std::move(scene), std::move(choice)};
}

// Beside the end of `walk`, within reach of it and out of reach of where it starts: the first such place
// (to its right, then its left, nearer first) that leaves the walk free, so that the wanderer takes it
// with giving way off.
std::optional<std::array<double, 2>> waiting_beside(const MotionGraph& g, const BoxedClip& walk) {
    const std::array<double, 2> end = clip_end(g, walk.clip, walk.place);
    const double dx = end[0] - walk.place.x, dy = end[1] - walk.place.y, len = std::hypot(dx, dy);
    for (const double side : {2.0, -2.0, 2.3, -2.3}) {
        const std::array<double, 2> at{end[0] + side * dy / len, end[1] - side * dx / len};
        if (std::hypot(at[0] - walk.place.x, at[1] - walk.place.y) < GiveWayTuning{}.reach) continue;
        if (wanderer(false, &at).second->taken().clip == walk.clip) return at;
    }
    return std::nullopt;
}

// A wanderer whose first free walk passes an agent that waits: with giving way on it takes a later walk
// that keeps clear of it; off, the first.
TEST(RuleUnits, GivingWayDefersAFreeWalkThatPassesAWaitingAgent) {
    const auto [alone, first] = wanderer(true, nullptr);
    ASSERT_EQ(first->outcome(), Outcome::Candidate);
    const BoxedClip walk = first->taken();
    ASSERT_TRUE(alone->escapes.moves[std::size_t(walk.clip)]);
    const std::optional<std::array<double, 2>> waiter = waiting_beside(alone->g, walk);
    ASSERT_TRUE(waiter) << "a waiting agent the walk passes, its plan free";
    const double reach = GiveWayTuning{}.reach;
    ASSERT_LT(nearest(alone->g, walk.clip, walk.place, *waiter), reach);
    const auto [scene_on, on] = wanderer(true, &*waiter);
    EXPECT_NE(on->taken().clip, walk.clip);
    EXPECT_TRUE(scene_on->escapes.moves[std::size_t(on->taken().clip)]) << "another walk";
    EXPECT_GE(nearest(scene_on->g, on->taken().clip, on->taken().place, *waiter), reach) << "clear of the waiter";
    // Tried in the same order: the walk passed over comes first.
    const auto& tried = on->point().candidates;
    const auto is = [](int clip) { return [clip](const Candidate& k) { return k.clip == clip; }; };
    EXPECT_LT(std::find_if(tried.begin(), tried.end(), is(walk.clip)),
              std::find_if(tried.begin(), tried.end(), is(on->taken().clip)));
}

}  // namespace
}  // namespace mobb::crowd
