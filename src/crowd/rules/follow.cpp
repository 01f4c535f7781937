#include "rules/follow.h"

#include <cmath>

#include "policy/follow.h"

namespace mobb::crowd {

std::optional<double> leader_facing(const FollowTuning& t, const CrowdState& s, int agent) {
    const Agent& a = s.agents[std::size_t(agent)];
    if (a.arrived || a.clips.empty()) return std::nullopt;
    const PlacedClip& playing = a.clips.back();
    const Placement end = s.graph.next(playing.place, playing.clip);
    // Near the goal it stops at for good, it is about to stand there: no one to follow.
    const auto goal = a.goal();
    if (goal && a.stops_at_goal() && std::hypot(end.x - (*goal)[0], end.y - (*goal)[1]) < t.goal_reach)
        return std::nullopt;
    return end.theta;
}

bool walks_on(const FollowTuning& t, const CrowdState& s, double way, const std::array<double, 2>& from,
              const Piece& other, LeaderFacing& leader) {
    if (other.index == 0) return false;
    const std::optional<double> facing = leader(t, s, other.agent);
    if (!facing) return false;
    const SpaceTimeBox b = box_of(other);
    return follows(way, from, {0.5 * (b.x0 + b.x1), 0.5 * (b.y0 + b.y1)}, *facing, t.angle);
}

}  // namespace mobb::crowd
