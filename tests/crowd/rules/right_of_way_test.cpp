// The right of way (src/crowd/rules/right_of_way.h) called alone on a state built by hand (rule_scene.h):
// who has it, which reservations may be rerouted, and a walker's reservation across every walk of one that
// waits rerouted clear of the walk taken.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "plan/choice_queries.h"
#include "rule_scene.h"
#include "rules/right_of_way.h"

namespace mobb::crowd {
namespace {

using namespace rule_test;  // Scene and the clips it places (rule_scene.h)

TEST(RuleUnits, RightOfWayGoesToOneThatHasNotMovedForAWhile) {
    const RightOfWayTuning t;
    const double dt = mobb::test::committed_graph().dt();
    Agent a;
    a.waiting_since = 30;
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
    EXPECT_FALSE(may_reroute(s, x.frame, s.pieces[std::size_t(clip)])) << "the clip it plays";
    for (int id : reserved) EXPECT_TRUE(may_reroute(s, x.frame, s.pieces[std::size_t(id)])) << id;
    EXPECT_FALSE(may_reroute(s, x.playing.frame + 1000, s.pieces[std::size_t(reserved[0])])) << "its clip has ended";
    EXPECT_FALSE(may_reroute(s, x.frame, s.pieces[x.scene.agents[std::size_t(x.waiter)].reserved[0]]))
        << "ground held from the start";
    x.scene.agents[std::size_t(x.walker)].arrived = true;
    EXPECT_FALSE(may_reroute(s, x.frame, s.pieces[std::size_t(reserved[0])])) << "at its goal for good";
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

// The walks of the one waiting (the successors of the walker's walk, placed at `base`) none of whose
// plans is free.
std::vector<PlacedCandidate> blocked_walks(const Crossing& x, const ChoiceBase& base) {
    std::vector<PlacedCandidate> out;
    for (int c : x.scene.g.clips[std::size_t(x.walk)].successors) {
        const auto frames = std::int64_t(x.scene.g.clips[std::size_t(c)].path.size());
        const PlacedCandidate pc =
            place_clip(x.scene.outlines[std::size_t(c)], c, frames, base.place, base.m, base.frame, nullptr);
        if (x.scene.escapes.moves[std::size_t(c)] && !plan_free(x.scene.state(), base, pc)) out.push_back(pc);
    }
    return out;
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
    const std::vector<PlacedCandidate> placed = blocked_walks(x, base);
    ASSERT_GE(placed.size(), 8u) << "the walker's reservation blocks most walks";
    ChoiceQueries q;
    q.start(x.waiter, x.frame);
    q.point().candidates.resize(placed.size());
    RightOfWayState io;
    Plan plan;
    EXPECT_EQ(take_right_of_way({true, 2.0, 0}, s, base, placed, int(placed.size()), q, io, plan), -1)
        << "none may be rerouted: nothing is taken";
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

}  // namespace
}  // namespace mobb::crowd
