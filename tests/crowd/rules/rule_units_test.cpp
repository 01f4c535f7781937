// Each rule of the choice point called alone (src/crowd/rules/, a header each) on a state built by hand -
// a few agents, what they play and reserve, walls - with its tuning, asserting what the rule decides:
// - leaving in stride: a clip ending within the goal radius of an exit is the whole plan;
// - following one's escape: the next clip of the plan reserved, else an idle clip inside the held ground;
// - the standing gap: exactly the routes whose held ground comes within the gap of another's;
// - giving way: who waits, and a free walk that passes one deferred for a later walk clear of it;
// - following: whom an agent follows, and which of a leader's pieces it plans past;
// - the look-ahead: candidates reordered by the best free sequence each leads to, round one who stands;
// - the right of way: who has it, which reservations may yield, and a walker's reservation rerouted;
// - stopping near walls: room to stand for goal agents' held ground, room to turn otherwise.
// The whole runs with each rule on and off are rules_test.cpp and rule_situations_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

#include "choice/choice.h"
#include "committed_graph.h"
#include "plan/crowd_state.h"
#include "rules/follow.h"
#include "rules/follow_escape.h"
#include "rules/give_way.h"
#include "rules/leave_in_stride.h"
#include "rules/look_ahead.h"
#include "rules/right_of_way.h"
#include "rules/stand_near_walls.h"
#include "rules/standing_gap.h"

namespace mobb::crowd {
namespace {

const MotionGraph& graph() { return test::committed_graph(); }

// A crowd's state built by hand, as the simulation keeps it (sim/simulation.h): agents, the pieces they
// reserved in the broad phase, the solids, the waiting agents. Not copied: the policy and the state hold
// references into it.
struct Scene {
    const MotionGraph& g = graph();
    const std::vector<ClipOutline> outlines = outlines_of(g);
    const NarrowPhase narrow = NarrowPhase::sweep(g);
    const EscapeTable escapes = EscapeTable::build(g);
    CrowdOptions options;
    std::unique_ptr<Policy> policy;
    double hold_clearance = 0;
    std::vector<Polygon> solids;
    BroadPhase solid_grid{4.0};
    BroadPhase broad{4.0};
    std::vector<Agent> agents;
    std::vector<Piece> pieces;
    BroadPhase waiting{4.0};
    std::vector<std::array<double, 2>> waiting_at;

    // A world [-20, 20]^2 with walls and `obstacles`, agents choosing by `select` (goals: every goal of the
    // run, for the goal policy's navigation fields).
    explicit Scene(Selection select = Selection::Avoid, std::vector<Polygon> obstacles = {},
                   std::vector<std::array<double, 2>> goals = {}) {
        options.world = {-20, -20, 20, 20, true, std::move(obstacles)};
        options.select = select;
        policy = make_policy(
            select, {g, options.world, escapes.in_place, std::move(goals), options.goal_radius, options.tuning});
        hold_clearance = escapes.turn_clearance;
        solids = options.world.solids();
        for (int k = 0; k < int(solids.size()); ++k) {
            const auto b = bounds(solids[std::size_t(k)]);
            solid_grid.insert(k, -1, {b[0], b[1], b[2], b[3], std::numeric_limits<std::int64_t>::min(), kForever});
        }
    }
    Scene(const Scene&) = delete;
    Scene& operator=(const Scene&) = delete;

    CrowdState state() const {
        return {g,      outlines,   narrow, escapes, *policy, options, hold_clearance,
                solids, solid_grid, broad,  agents,  pieces,  waiting, waiting_at};
    }

    int add_agent(const Placement& start) {
        agents.emplace_back().start = start;
        waiting_at.push_back({0, 0});
        return int(agents.size()) - 1;
    }
    // A piece in the broad phase, placed after every piece before it.
    int place(Piece p) {
        p.seq = std::int64_t(pieces.size());
        pieces.push_back(p);
        broad.insert(int(pieces.size()) - 1, p.agent, box_of(p));
        return int(pieces.size()) - 1;
    }
    // Agent `a` plays `clip` placed at `p` from `frame` on, committed at choice point `choice`.
    BoxedClip play(int a, int clip, const Placement& p, std::int64_t frame, int choice = 0) {
        agents[std::size_t(a)].clips.push_back({clip, frame, p, false, choice});
        Piece piece;
        piece.agent = a;
        piece.choice = choice;
        piece.clip = frame_clip(state(), clip, p, Rigid2::of(p), frame);
        place(piece);
        return piece.clip;
    }
    // Agent `a` reserves `plan` (its escape clips, its held ground), as Simulation::reserve does.
    void reserve(int a, const Plan& plan, int choice = 0) {
        Agent& agent = agents[std::size_t(a)];
        Piece p;
        p.agent = a;
        p.choice = choice;
        for (std::size_t i = 0; i < plan.escape.size(); ++i) {
            p.index = int(i) + 1;
            p.clip = plan.escape[i];
            agent.reserved.push_back(place(p));
        }
        if (plan.hold) {
            p.kind = Piece::Held;
            p.index = -1;
            p.hold = *plan.hold;
            agent.reserved.push_back(place(p));
        }
        agent.plan = plan;
    }
    // Agent `a` waits on the ground it holds (giving way: as Simulation::apply_waiting marks it).
    void wait(int a) {
        const Hold& h = *agents[std::size_t(a)].plan.hold;
        waiting_at[std::size_t(a)] = {h.x, h.y};
        waiting.insert(a, a, waiting_ground(options.tuning.give_way, h));
    }
    // Agent `a` stands at its start for good: the ground it holds there (choice -1, as at a run's start).
    void stand(int a) {
        const Placement& s = agents[std::size_t(a)].start;
        reserve(a, Plan{{}, Hold{s.x, s.y, escapes.hold_radius, 0}}, -1);
    }
};

// Clip `clip` placed at `p` from frame 0 on, as a choice point places its candidates.
PlacedCandidate candidate(const Scene& s, int clip, const Placement& p) {
    const auto frames = std::int64_t(s.g.clips[std::size_t(clip)].path.size());
    return place_clip(s.outlines[std::size_t(clip)], clip, frames, p, Rigid2::of(p), 0, nullptr);
}

// The walking clips of the graph, those that go farthest first.
std::vector<int> walks(const MotionGraph& g) {
    std::vector<int> out;
    for (int c = 0; c < int(g.clips.size()); ++c)
        if (kind_of(g.clips[std::size_t(c)], c) == ClipKind::Walk) out.push_back(c);
    const auto reach = [&](int c) {
        return std::hypot(g.clips[std::size_t(c)].exit_x, g.clips[std::size_t(c)].exit_y);
    };
    std::stable_sort(out.begin(), out.end(), [&](int a, int b) { return reach(a) > reach(b); });
    return out;
}

// ---- Leaving in stride ----

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

// ---- Following one's escape ----

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
    ASSERT_TRUE(follow_escape(scene.state(), base, clip, rest));
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
    ASSERT_TRUE(follow_escape(scene.state(), {a, frame, base, Rigid2::of(base)}, clip, plan));
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
    EXPECT_FALSE(follow_escape(scene.state(), {a, frame, base, Rigid2::of(base)}, clip, plan));
    scene.agents[std::size_t(a)].plan.hold.reset();
    EXPECT_FALSE(follow_escape(scene.state(), {a, frame, base, Rigid2::of(base)}, clip, plan)) << "no ground held";
}

// ---- The standing gap ----

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

// ---- Giving way ----

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
        s2.wait(w);
        const bool passes = nearest(s2.g, walk, at, s2.waiting_at[std::size_t(w)]) < t.reach;
        EXPECT_EQ(passes_waiting(t, s2.state(), base, c, scratch), passes) << side;
        EXPECT_FALSE(passes_waiting({false}, s2.state(), base, c, scratch)) << "the rule off";
        (passes ? passing : clear)++;
    }
    EXPECT_GT(passing, 0);
    EXPECT_GT(clear, 0);
    // The agent's own waiting is none of its concern.
    scene.stand(base.agent);
    scene.wait(base.agent);
    EXPECT_FALSE(passes_waiting(t, scene.state(), base, c, scratch));
}

TEST(RuleUnits, GivingWayCountsAsWaitingOneThatHasNotMovedForAWhile) {
    const GiveWayTuning t;
    const double dt = graph().dt();
    Agent a;
    a.plan.hold = Hold{0, 0, 0.4, 0};
    a.moved_until = 100;
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

// A wanderer whose first free walk passes an agent that waits: with giving way on it takes a later walk
// that keeps clear of it; off, the first.
TEST(RuleUnits, GivingWayDefersAFreeWalkThatPassesAWaitingAgent) {
    const auto evaluate = [](bool on, const std::array<double, 2>* waiter) {
        auto scene = std::make_unique<Scene>();
        scene->options.tuning.give_way.on = on;
        const int a = scene->add_agent({0, 0, 0, 0});
        scene->stand(a);
        if (waiter) {
            const int w = scene->add_agent({(*waiter)[0], (*waiter)[1], 0, 0});
            scene->stand(w);
            scene->wait(w);
        }
        auto choice = std::make_unique<Choice>();
        choice->prepare(scene->state(), a, 0);
        choice->evaluate(scene->state());
        return std::make_pair(std::move(scene), std::move(choice));
    };
    const auto [alone, first] = evaluate(true, nullptr);
    ASSERT_EQ(first->outcome(), Outcome::Candidate);
    const BoxedClip walk = first->taken();
    ASSERT_TRUE(alone->escapes.moves[std::size_t(walk.clip)]);
    // Beside the end of that walk, within reach of it and out of reach of where it starts: the first
    // such place (to its right, then its left, nearer first) that leaves the walk free.
    const std::array<double, 2> end = clip_end(alone->g, walk.clip, walk.place);
    const double dx = end[0] - walk.place.x, dy = end[1] - walk.place.y, len = std::hypot(dx, dy);
    const double reach = GiveWayTuning{}.reach;
    std::array<double, 2> waiter{};
    bool found = false;
    for (const double side : {2.0, -2.0, 2.3, -2.3}) {
        waiter = {end[0] + side * dy / len, end[1] - side * dx / len};
        if (std::hypot(waiter[0] - walk.place.x, waiter[1] - walk.place.y) < reach) continue;
        if ((found = evaluate(false, &waiter).second->taken().clip == walk.clip)) break;
    }
    ASSERT_TRUE(found) << "a waiting agent the walk passes, its plan free";
    ASSERT_LT(nearest(alone->g, walk.clip, walk.place, waiter), reach);
    const auto [scene_on, on] = evaluate(true, &waiter);
    EXPECT_NE(on->taken().clip, walk.clip);
    EXPECT_TRUE(scene_on->escapes.moves[std::size_t(on->taken().clip)]) << "another walk";
    EXPECT_GE(nearest(scene_on->g, on->taken().clip, on->taken().place, waiter), reach) << "clear of the waiter";
    // Tried in the same order: the walk passed over comes first.
    const auto& tried = on->point().candidates;
    const auto is = [](int clip) { return [clip](const Candidate& k) { return k.clip == clip; }; };
    EXPECT_LT(std::find_if(tried.begin(), tried.end(), is(walk.clip)),
              std::find_if(tried.begin(), tried.end(), is(on->taken().clip)));
}

// ---- Following ----

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

// ---- The look-ahead ----

// A goal agent at the origin facing its goal 10 m east, one agent standing 3 m ahead on its way: the
// look-ahead reorders its candidates by sequences that go round, every step free of the one standing.
TEST(RuleUnits, LookAheadOrdersTheCandidatesByTheirBestFreeSequence) {
    Scene scene(Selection::Goal, {}, {{10, 0}});
    const Placement at{0, 0, 0, 0};
    const ChoiceBase base{scene.add_agent(at), 0, at, Rigid2::of(at)};
    scene.agents[std::size_t(base.agent)].goals = {{10, 0}};
    scene.stand(base.agent);
    scene.stand(scene.add_agent({3, 0, M_PI, 0}));
    const Piece& standing = scene.pieces.back();
    const CrowdState s = scene.state();
    const ChoiceSite site{base.agent, at, std::array<double, 2>{10, 0}, true, 0, false, std::nullopt, {}};
    // The successors of a walk with many: the candidates of an agent walking.
    std::vector<int> policy;
    for (int walk : walks(scene.g))
        if (policy.size() < 8) policy = scene.g.clips[std::size_t(walk)].successors;
    s.policy.order(site, policy);
    LookAheadTuning t;
    t.budget = 2000;  // every candidate's search to the horizon
    std::vector<int> order = policy;
    LookAheadState io;
    ChoiceQueries q;
    q.start(base.agent, 0);
    look_ahead(t, {}, s, base, site, q, order, io);
    ASSERT_TRUE(io.searched);
    EXPECT_LE(io.search.tested(), t.budget);
    EXPECT_GT(q.point().queries, 0u) << "its steps are tested, and counted for the choice point";
    std::vector<int> sorted = order, before = policy;
    std::sort(sorted.begin(), sorted.end()), std::sort(before.begin(), before.end());
    EXPECT_EQ(sorted, before) << "the same candidates";
    for (std::size_t k = 0; k < order.size(); ++k) EXPECT_EQ(order[k], policy[std::size_t(io.ranked[k].second)]);
    for (std::size_t k = 1; k < order.size(); ++k)
        EXPECT_LE(io.ranked[k - 1].first, io.ranked[k].first) << "the best sequence first";
    // The sequences found: whole, and every step clear of the one standing; the first one found in the
    // order is what the choice point intends after its first clip.
    int whole = 0, first = -1;
    for (std::size_t k = 0; k < order.size(); ++k) {
        const std::vector<SearchStep> seq = io.search.sequence(io.ranked[k].second);
        if (seq.empty()) continue;
        ++whole;
        if (first < 0) first = int(k);
        ASSERT_EQ(int(seq.size()), scene.options.tuning.goal.horizon);
        EXPECT_EQ(seq[0].clip, order[k]);
        for (const SearchStep& step : seq) {
            Piece p;
            p.clip = frame_clip(s, step.clip, step.place, Rigid2::of(step.place), step.frame);
            EXPECT_FALSE(pieces_collide(s, p, standing, nullptr));
        }
    }
    ASSERT_GT(whole, 0);
    EXPECT_LT(whole, int(order.size())) << "some walks lead only into the one standing";
    std::vector<SearchStep> intended;
    intended_after(io, first, intended);
    const std::vector<SearchStep> seq = io.search.sequence(io.ranked[std::size_t(first)].second);
    ASSERT_EQ(intended.size(), seq.size() - 1);
    EXPECT_EQ(intended[0].clip, seq[1].clip);
    ASSERT_FALSE(io.learned.empty());
    EXPECT_EQ(io.learned.back()[0], at.x) << "the time to go learned where it stands";
    EXPECT_EQ(io.learned.back()[2], io.ranked[0].first);
    // Off, the policy's order stays.
    order = policy;
    look_ahead({false}, {}, s, base, site, q, order, io);
    EXPECT_FALSE(io.searched);
    EXPECT_EQ(order, policy);
    intended_after(io, 0, intended);
    EXPECT_TRUE(intended.empty());
}

// ---- The right of way ----

TEST(RuleUnits, RightOfWayGoesToOneThatHasNotMovedForAWhile) {
    const RightOfWayTuning t;
    const double dt = graph().dt();
    Agent a;
    a.moved_until = 30;
    const auto after = std::int64_t(std::ceil(t.after / dt));
    EXPECT_TRUE(has_right_of_way(t, a, 30 + after, dt, false));
    EXPECT_FALSE(has_right_of_way(t, a, 30 + after - 1, dt, false)) << "not yet";
    EXPECT_FALSE(has_right_of_way(t, a, 30 + after, dt, true)) << "arriving: it stops";
    EXPECT_FALSE(has_right_of_way({false}, a, 30 + after, dt, false)) << "the rule off";
}

// A walker heading south towards the ground east of one that waits at the origin: at frame `frame`
// it is 5 frames short of the end of the walk it plays, with its plan along its first escape route
// reserved.
struct Crossing {
    Scene scene;
    int waiter = 0, walker = 0;
    int walk = 0;
    std::int64_t frame = 0;
    BoxedClip playing;

    explicit Crossing(const std::array<double, 2>& from) {
        walk = -1;
        for (int w : walks(scene.g))
            if (walk < 0 && scene.g.clips[std::size_t(w)].successors.size() >= 8) walk = w;
        waiter = scene.add_agent({0, 0, 0, 0});
        scene.stand(waiter);
        walker = scene.add_agent({from[0], from[1], -M_PI / 2, 0});
        const auto len = std::int64_t(scene.g.clips[std::size_t(walk)].path.size());
        frame = len - 5;
        playing = scene.play(walker, walk, {from[0], from[1], -M_PI / 2, 0}, 0, 1);
        scene.reserve(walker, plan_along(scene.state(), playing, scene.escapes.routes[std::size_t(walk)].front()), 1);
    }
};

TEST(RuleUnits, RightOfWayMovesOnlyTheReservationsOfAgentsWalkingOn) {
    Crossing x({2, 6});
    const CrowdState s = x.scene.state();
    const std::vector<int>& reserved = x.scene.agents[std::size_t(x.walker)].reserved;
    const int clip = int(x.scene.pieces.size()) - 1 - int(reserved.size());
    EXPECT_FALSE(may_yield(s, x.frame, s.pieces[std::size_t(clip)])) << "the clip it plays";
    for (int id : reserved) EXPECT_TRUE(may_yield(s, x.frame, s.pieces[std::size_t(id)])) << id;
    EXPECT_FALSE(may_yield(s, x.playing.frame + 1000, s.pieces[std::size_t(reserved[0])])) << "its clip has ended";
    EXPECT_FALSE(may_yield(s, x.frame, s.pieces[x.scene.agents[std::size_t(x.waiter)].reserved[0]]))
        << "ground held from the start";
    x.scene.agents[std::size_t(x.walker)].arrived = true;
    EXPECT_FALSE(may_yield(s, x.frame, s.pieces[std::size_t(reserved[0])])) << "at its goal for good";
}

// Whether candidate `c` has an escape route whose plan is free (the candidates' test, no right of way).
bool plan_free(const CrowdState& s, const ChoiceBase& base, const PlacedCandidate& c) {
    ChoiceQueries q;
    q.start(base.agent, base.frame);
    q.point().candidates.resize(1);
    Piece mine;
    mine.clip = {c.clip, c.place, base.frame, c.box, base.m};
    if (!q.candidate_free(s, 0, mine, Hits::Stop)) return false;
    Plan plan;
    for (const std::vector<int>& route : s.escapes.routes[std::size_t(c.clip)])
        if (build_plan(s, mine.clip, route, plan,
                       [&](const Piece& p) { return q.candidate_free(s, 0, p, Hits::Stop); }))
            return true;
    return false;
}

// The pieces of a plan taken: its clip, escape clips and held ground, as the agent's.
std::vector<Piece> pieces_of(int agent, const BoxedClip& clip, const Plan& plan) {
    std::vector<Piece> out(1);
    out[0].agent = agent;
    out[0].clip = clip;
    for (const BoxedClip& e : plan.escape) out.push_back(out[0]), out.back().clip = e;
    if (plan.hold) out.push_back(out[0]), out.back().kind = Piece::Held, out.back().hold = *plan.hold;
    return out;
}

// The walker's reservation lies across every walk of the one waiting: with the right of way, it takes
// one, and the walker stops another way, clear of that walk's plan.
TEST(RuleUnits, RightOfWayReroutesAWalkersReservation) {
    Crossing x({1.5, 3.5});
    const CrowdState s = x.scene.state();
    const Placement at{0, 0, 0, x.scene.g.dt() * double(x.frame)};
    const ChoiceBase base{x.waiter, x.frame, at, Rigid2::of(at)};
    // Its walks, none with a free plan.
    std::vector<PlacedCandidate> placed;
    for (int c : x.scene.g.clips[std::size_t(x.walk)].successors) {
        const auto frames = std::int64_t(x.scene.g.clips[std::size_t(c)].path.size());
        const PlacedCandidate pc =
            place_clip(x.scene.outlines[std::size_t(c)], c, frames, at, base.m, x.frame, nullptr);
        if (x.scene.escapes.moves[std::size_t(c)] && !plan_free(s, base, pc)) placed.push_back(pc);
    }
    ASSERT_GE(placed.size(), 8u) << "the walker's reservation blocks most walks";
    ChoiceQueries q;
    q.start(x.waiter, x.frame);
    q.point().candidates.resize(placed.size());
    RightOfWayState io;
    Plan plan;
    EXPECT_EQ(take_right_of_way({true, 2.0, 0}, s, base, placed, int(placed.size()), q, io, plan), -1)
        << "none may yield: nothing is taken";
    EXPECT_TRUE(io.reroutes.empty());
    const int k = take_right_of_way({}, s, base, placed, int(placed.size()), q, io, plan);
    ASSERT_GE(k, 0);
    EXPECT_GT(q.point().candidates[std::size_t(k)].queries, 0) << "its queries count for the candidate";
    ASSERT_EQ(io.reroutes.size(), 1u);
    const Reroute& r = io.reroutes[0];
    EXPECT_EQ(r.agent, x.walker);
    // What it releases: the walker's reservation, which the plan taken meets.
    const PlacedCandidate& c = placed[std::size_t(k)];
    const std::vector<Piece> taken = pieces_of(x.waiter, {c.clip, c.place, x.frame, c.box, base.m}, plan);
    const std::vector<int>& old = x.scene.agents[std::size_t(x.walker)].reserved;
    ASSERT_EQ(r.released.size(), old.size());
    bool meets = false;
    for (std::size_t i = 0; i < old.size(); ++i) {
        const Piece& o = s.pieces[std::size_t(old[i])];
        EXPECT_EQ(r.released[i].x0, box_of(o).x0);
        for (const Piece& t : taken) meets = meets || pieces_collide(s, t, o, nullptr);
    }
    EXPECT_TRUE(meets) << "the plan taken meets the reservation it moves";
    // Its new way to stop: from the end of the clip it plays, clear of the plan taken.
    ASSERT_TRUE(r.plan.hold);
    const std::int64_t end = x.playing.frame + std::int64_t(x.scene.g.clips[std::size_t(x.walk)].path.size());
    EXPECT_EQ(r.plan.escape.empty() ? r.plan.hold->frame : r.plan.escape[0].frame, end);
    const std::vector<Piece> rerouted = pieces_of(x.walker, x.playing, r.plan);
    for (std::size_t i = 1; i < rerouted.size(); ++i)  // after the clip it plays
        for (const Piece& t : taken)
            EXPECT_FALSE(pieces_collide(s, rerouted[i], t, nullptr)) << "the reroute is clear of the plan taken";
}

// ---- Stopping near walls ----

// A goal agent may hold ground in a door 1.6 m wide with the rule on (room to stand), not with it off
// (room to turn), and a wanderer never: meets_solid with the clearance the rule gives.
TEST(RuleUnits, StandingNearWallsLetsGoalAgentsStopWithRoomToStand) {
    const std::vector<Polygon> door{Polygon::rectangle(-0.5, -4, 0.5, -0.8), Polygon::rectangle(-0.5, 0.8, 0.5, 4)};
    Scene goal(Selection::Goal, door, {{5, 0}}), wander(Selection::Avoid, door);
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
