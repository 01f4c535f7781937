// A crowd's state built by hand (Scene) for the unit tests of the choice point's rules (tests/crowd/rules/,
// a test file per rule), which call a rule alone on it; and the clips they place. Needs MOBB_SOURCE_DIR.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "committed_graph.h"
#include "plan/crowd_state.h"

namespace mobb::crowd::rule_test {

// A crowd's state built by hand, as the simulation keeps it (sim/simulation.h): agents, the pieces they
// reserved in the broad phase, the solids, the waiting agents. Not copied: the policy and the state hold
// references into it.
struct Scene {
    const MotionGraph& g = mobb::test::committed_graph();
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
    explicit Scene(Selection select = Selection::Wander, std::vector<Polygon> obstacles = {},
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
        plan_pieces(a, choice, plan, [&](const Piece& p) { agent.reserved.push_back(place(p)); });
        agent.plan = plan;
    }
    // Agent `a` stands at its start for good: the ground it holds there (choice -1, as at a run's start).
    void stand(int a) {
        const Placement& s = agents[std::size_t(a)].start;
        reserve(a, Plan{{}, Hold{s.x, s.y, escapes.hold_radius, 0}}, -1);
    }
};

// Clip `clip` placed at `p` from frame 0 on, as a choice point places its candidates.
inline PlacedCandidate candidate(const Scene& s, int clip, const Placement& p) {
    const auto frames = std::int64_t(s.g.clips[std::size_t(clip)].path.size());
    return place_clip(s.outlines[std::size_t(clip)], clip, frames, p, Rigid2::of(p), 0, nullptr);
}

// The walking clips of the graph, those that go farthest first.
inline std::vector<int> walks(const MotionGraph& g) {
    std::vector<int> out;
    for (int c = 0; c < int(g.clips.size()); ++c)
        if (kind_of(g.clips[std::size_t(c)], c) == ClipKind::Walk) out.push_back(c);
    const auto reach = [&](int c) {
        return std::hypot(g.clips[std::size_t(c)].exit_x, g.clips[std::size_t(c)].exit_y);
    };
    std::stable_sort(out.begin(), out.end(), [&](int a, int b) { return reach(a) > reach(b); });
    return out;
}

}  // namespace mobb::crowd::rule_test
