// Following (CrowdTuning::follow): beyond its first clip, a goal agent's look-ahead plans past the
// reservations of agents that face its way - their escape clips and held ground, never the clip they
// play - since they are expected to walk on. Held ground is what an agent would stop on if it found no
// way on, and an agent walking down the same path as another finds its way on as the one ahead does: a
// queue at a door moves. Without this rule the search treats each such reservation as a wall for good,
// and the agents behind walk round the queue or turn away from it, then back (bench/results/log.md,
// "Following"). Silver's windowed cooperative A* (2005) likewise trusts reservations only within a
// window. The first clip, with its escape, is still tested against everything, so the crowd stays
// collision-free; this only changes which free clip ranks first.
#include "policy/follow.h"

#include <cmath>

#include "choice/choice.h"

namespace mobb::crowd {

std::optional<double> leader_facing(const CrowdState& s, int agent) {
    const Agent& a = s.agents[std::size_t(agent)];
    if (a.arrived || a.clips.empty()) return std::nullopt;
    const PlacedClip& playing = a.clips.back();
    const Placement end = s.graph.next(playing.place, playing.clip);
    // Near the goal it stops at for good, it is about to stand there: no one to follow.
    const auto goal = a.goal();
    const double reach = s.options.tuning.follow.goal_reach;
    if (goal && a.stops_at_goal() && std::hypot(end.x - (*goal)[0], end.y - (*goal)[1]) < reach) return std::nullopt;
    return end.theta;
}

// Whether another agent's piece is a reservation the searching agent may plan past: one of a leader it
// follows (follow.h), and not the clip that leader plays, which is certain.
bool Choice::walks_on(const CrowdState& s, const Piece& other) const {
    if (other.index == 0 || !way_heading_) return false;
    const std::optional<double> facing = leader_facing(s, other.agent);
    if (!facing) return false;
    const SpaceTimeBox b = box_of(other);
    return follows(*way_heading_, {base_.place.x, base_.place.y}, {0.5 * (b.x0 + b.x1), 0.5 * (b.y0 + b.y1)}, *facing,
                   s.options.tuning.follow.angle);
}

}  // namespace mobb::crowd
