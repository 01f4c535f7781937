// The right of way (RightOfWayTuning): an agent that has not moved for `after` seconds may take a moving
// candidate whose plan meets other agents' reservations - the escape clips and held ground beyond the
// clip they play, never the clip itself - when each of those agents (at most `max_rerouted`, none at a
// choice point in the frame, none standing) has another escape route from the clip it plays, free of
// everything else and of the new plan. The other agent then reserves that route instead: safe as before,
// it just stops elsewhere. Priority to the agent that waited, as in Okumura et al.'s priority inheritance
// with backtracking (PIBT, 2019): the higher-priority agent pushes the lower ones, which plan again. The
// right of way also passes the standing gap: one that waited may stop close (keeping the gap there too
// made the idle tail longer: bench/results/log.md).
#pragma once
#include <cstdint>
#include <vector>

#include "mobb/crowd/tuning.h"
#include "plan/choice_queries.h"
#include "plan/crowd_state.h"

namespace mobb::crowd {

/// A choice point's right of way: the others' plans that give way to the plan it takes, and its scratch.
struct RightOfWayState {
    std::vector<Reroute> reroutes;  ///< the other agents' plans that give way to the plan taken
    std::vector<int> rerouted;      ///< owners of the reservations the plan being tried meets: to reroute
    std::vector<int> excluded;      ///< broad-phase ids released if it is taken (theirs and its own)
    std::vector<Piece> extra;       ///< the new plan's pieces and the reroutes found so far
};

/// Whether agent `a`, at a choice point at `frame` (frames of `dt` seconds), has the right of way: it is
/// not arriving and has played no moving clip (EscapeTable::moves) for `after` seconds. Never with the
/// rule off.
bool has_right_of_way(const RightOfWayTuning& t, const Agent& a, std::int64_t frame, double dt, bool arriving);

/// Whether another agent's piece may give way to a plan with the right of way at `frame`: a reservation
/// (an escape clip or held ground, not the clip it plays nor where it started) of an agent playing a clip
/// that moves beyond `frame` (not at a choice point now, not standing, not at its goal).
bool may_reroute(const CrowdState& s, std::int64_t frame, const Piece& other);

/// The moving candidates among the first `end` of `placed` (all starting at `base`) again, in order, now
/// past the reservations that may be rerouted, of at most `max_rerouted` owners: the first with an escape route
/// whose plan is free but for them, and whose owners all find another way to stop, is taken - its index
/// is returned, its plan is `out_plan` and the owners' new plans io.reroutes. -1 when none is (no
/// reroutes then). The queries count for the candidates in `q`.
int take_right_of_way(const RightOfWayTuning& t, const CrowdState& s, const ChoiceBase& base,
                      const std::vector<PlacedCandidate>& placed, int end, ChoiceQueries& q, RightOfWayState& io,
                      Plan& out_plan);

}  // namespace mobb::crowd
