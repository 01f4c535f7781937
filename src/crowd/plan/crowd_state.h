// The state a crowd choice point reads (CrowdState): the agents, the pieces they reserved in the broad
// phase, the solids, the graph's escapes; and the tests of a plan's pieces against it - the walls and
// obstacles, the others' pieces - and the building of plans along escape routes. Frozen while a frame's
// choice points are evaluated. Private to src/crowd.
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "mobb/core/query.h"
#include "mobb/crowd/collision/broad_phase.h"
#include "mobb/crowd/collision/narrow_phase.h"
#include "mobb/crowd/options.h"
#include "mobb/crowd/policy/policy.h"
#include "plan/clip_outline.h"
#include "plan/escape.h"
#include "plan/learned_cost.h"
#include "plan/plan.h"

namespace mobb::crowd {

/// One agent of the simulation.
struct Agent {
    Placement start;
    std::int64_t start_frame = 0;              ///< stands at its start until then
    std::vector<std::array<double, 2>> goals;  ///< AgentSpec::goals, reached in turn
    std::size_t next_goal = 0;                 ///< the one it heads for now
    AtGoal at_goal = AtGoal::Stay;
    std::optional<std::int64_t> left_frame;  ///< it left the run then (AtGoal::Leave)
    std::vector<PlacedClip> clips;           ///< committed, in time order
    Plan plan;                               ///< reserved beyond its last clip
    std::vector<int> reserved;               ///< broad-phase ids of the plan's pieces
    bool arrived = false;                    ///< reached its goal: stays for good
    int choices_waited = 0;          ///< choice points in a row at which it waited: took its escape or stayed in place
    std::int64_t waiting_since = 0;  ///< frame its last clip that moves (EscapeTable::moves) ended, or its start
    LearnedCost learned;             ///< what its look-aheads learned of the time to go (learned_cost.h)

    /// The goal it heads for now; nothing for an agent that wanders.
    std::optional<std::array<double, 2>> goal() const {
        if (next_goal >= goals.size()) return std::nullopt;
        return goals[next_goal];
    }
    /// Whether it stands at the goal it heads for for good: the last one, and it stays.
    bool stops_at_goal() const { return next_goal + 1 == goals.size() && at_goal == AtGoal::Stay; }
};

/// What a choice point reads, all of it frozen while a frame's choice points are evaluated.
struct CrowdState {
    const MotionGraph& graph;
    const std::vector<ClipOutline>& outlines;  ///< one per graph clip
    const NarrowPhase& narrow;
    const EscapeTable& escapes;
    const Policy& policy;
    const CrowdOptions& options;
    /// Metres held ground keeps from the solids: room to stand or to turn (rules/stand_near_walls.h).
    double hold_clearance;
    const std::vector<Polygon>& solids;  ///< World::solids(), by solid index
    const BroadPhase& solid_grid;        ///< the solids' bounds, by solid index (owner -1)
    const BroadPhase& broad;             ///< pieces live now
    const std::vector<Agent>& agents;
    const std::vector<Piece>& pieces;  ///< by broad-phase id
    const BroadPhase& waiting;         ///< agents that wait (giving way: GiveWayTuning::after), by id (their ground)
    const std::vector<std::array<double, 2>>& waiting_at;  ///< per agent: where it waits (metres)
};

/// Where a choice point's candidates start: whose choice point it is, at which frame, the placement
/// there (its t0 on the global frame grid) and its rotation m = Rigid2::of(place).
struct ChoiceBase {
    int agent = 0;
    std::int64_t frame = 0;
    Placement place;
    Rigid2 m;
};

/// Where clip `clip` of `g`, placed at `place`, leaves the agent's disk: its last sample in the world
/// (metres). Simulation::reach_goals and leaving in stride (leaves_in_stride) both judge arrival by it
/// and reaches_goal, so they agree to the bit: a leaver holds no ground beyond the exit it reaches.
std::array<double, 2> clip_end(const MotionGraph& g, int clip, const Placement& place);
/// Whether a disk centred at `p` has reached `goal`: closer than `radius` metres (CrowdOptions::goal_radius).
bool reaches_goal(const std::array<double, 2>& p, const std::array<double, 2>& goal, double radius);

/// Graph clip `clip` placed at `p` (rotation m) from frame `frame` on, with its box.
BoxedClip frame_clip(const CrowdState& s, int clip, const Placement& p, const Rigid2& m, std::int64_t frame);

/// The plan of clip `c` along an escape route (EscapeTable::routes): its stopping clips chained after it
/// on the frame grid, and the held ground where the route's clip in place starts.
Plan plan_along(const CrowdState& s, const BoxedClip& c, const std::vector<int>& route);

// The plan of clip `c` along an escape route, built piece by piece: its stopping clips chained after it
// on the frame grid, then the held ground where the route's idle clip starts. Each piece goes to
// `accept` as it is placed, and the plan stops at the first it refuses; returns whether none was.
template <class Accept>
bool build_plan(const CrowdState& s, const BoxedClip& c, const std::vector<int>& route, Plan& plan, Accept&& accept) {
    // (The route's first i + 1 clips place its i-th piece: a refused escape clip refuses every route
    // sharing that prefix, which the caller skips.)
    const MotionGraph& g = s.graph;
    plan.escape.clear();
    plan.hold.reset();
    int prev = c.clip;
    Placement p = c.place;
    Rigid2 m = c.m;
    std::int64_t f = c.frame + std::int64_t(g.clips[std::size_t(prev)].path.size());
    Piece piece;
    for (std::size_t i = 0; i < route.size(); ++i) {
        p = g.next(p, m, prev);
        p.t0 = double(f) * g.dt();
        if (i + 1 == route.size()) break;  // the idle clip: the held ground starts with it
        m = Rigid2::of(p);
        piece.index = int(i) + 1;
        piece.clip = frame_clip(s, route[i], p, m, f);
        plan.escape.push_back(piece.clip);
        if (!accept(piece)) return false;
        prev = route[i];
        f += std::int64_t(g.clips[std::size_t(prev)].path.size());
    }
    plan.hold = Hold{p.x, p.y, s.escapes.hold_of(route.back()), f};
    piece.kind = Piece::Held;
    piece.index = -1;
    piece.hold = *plan.hold;
    return accept(piece);
}

/// Whether piece `mine` of an agent's plan collides with another agent's piece: clips by the narrow
/// phase; a clip and held ground by their samples overlapping the held disk from its first frame on;
/// two held grounds by their disks.
bool pieces_collide(const CrowdState& s, const Piece& mine, const Piece& other, QueryStats* stats);

/// The broad-phase ids of the live pieces of agents other than `owner` whose boxes overlap `box`
/// (BroadPhase::query), in the order they were placed (Piece::seq): answers do not depend on which ids
/// were reused.
void query_pieces(const CrowdState& s, const SpaceTimeBox& box, int owner, std::vector<int>& out);
/// Whether it meets solid k: a clip's samples by disk_overlaps(); held ground when the solid is nearer
/// than CrowdState::hold_clearance.
bool meets_solid(const CrowdState& s, const Piece& mine, int k);

}  // namespace mobb::crowd
