// Following (FollowTuning): beyond its first clip, a goal agent's look-ahead plans past the
// reservations of agents that face its way - their escape clips and held ground, never the clip they
// play - since they are expected to walk on. Held ground is what an agent would stop on if it found no
// way on, and an agent walking down the same path as another finds its way on as the one ahead does: a
// queue at a door moves. Without this rule the search treats each such reservation as a wall for good,
// and the agents behind walk round the queue or turn away from it, then back (bench/results/log.md,
// "Following"). Silver's windowed cooperative A* (2005) likewise trusts reservations only within a
// window. The first clip, with its escape, is still tested against everything, so the crowd stays
// collision-free; this only changes which free clip ranks first.
#pragma once
#include <array>
#include <optional>

#include "mobb/crowd/tuning.h"
#include "plan/crowd_state.h"

namespace mobb::crowd {

/// The way agent `agent` faces at the end of the clip it plays (radians, world frame) when others may
/// follow it; none when it stopped for good, ends that clip within `goal_reach` of the goal it stops at
/// (it is about to), or has played no clip yet.
std::optional<double> leader_facing(const FollowTuning& t, const CrowdState& s, int agent);

/// leader_facing() keeping the last agent's answer: the pieces a query finds come in runs of one agent's
/// (by seq), so a choice point works it out once a run rather than once a piece. For one state only.
class LeaderFacing {
public:
    std::optional<double> operator()(const FollowTuning& t, const CrowdState& s, int agent) {
        if (agent != agent_) agent_ = agent, facing_ = leader_facing(t, s, agent);
        return facing_;
    }

private:
    int agent_ = -1;
    std::optional<double> facing_;
};

/// Whether another agent's piece is a reservation that an agent at `from` wanting to go `way` (radians)
/// may plan past: one of a leader it follows (leader_facing, follows() within `angle`), and not the clip
/// that leader plays, which is certain. `leader` keeps the facing of the last agent asked about.
bool walks_on(const FollowTuning& t, const CrowdState& s, double way, const std::array<double, 2>& from,
              const Piece& other, LeaderFacing& leader);
inline bool walks_on(const FollowTuning& t, const CrowdState& s, double way, const std::array<double, 2>& from,
                     const Piece& other) {
    LeaderFacing facing;
    return walks_on(t, s, way, from, other, facing);
}

}  // namespace mobb::crowd
