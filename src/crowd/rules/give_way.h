// Giving way (GiveWayTuning): a free moving candidate whose clip passes within `reach` of an agent that
// has not moved for `after` seconds (CrowdState::waiting) is taken only when no later moving candidate is
// free and clear of such agents: walkers keep out of the way of those who wait, when they can, so that
// the ground they would walk into stays open. It only reorders free candidates: nothing is refused for
// it. Two sides: the simulation marks who waits (waits, waiting_ground), and a choice point defers a
// walk that passes one (passes_waiting, GiveWayState).
#pragma once
#include <cstdint>
#include <vector>

#include "mobb/crowd/tuning.h"
#include "plan/crowd_state.h"

namespace mobb::crowd {

/// A choice point's walk deferred to give way.
struct GiveWayState {
    int deferred = -1;         ///< the first free moving candidate that passes a waiting agent; -1: none yet
    Plan plan;                 ///< its plan
    std::vector<int> waiters;  ///< scratch: the waiting agents near a candidate

    /// Candidate k, free with `p` but passing a waiting agent, is deferred: taken only when no later walk
    /// is free and clear of waiting agents. The first one deferred stays.
    void defer(int k, const Plan& p) {
        if (deferred < 0) deferred = k, plan = p;
    }
};

/// Whether candidate `c` (placed at base.place) passes within `reach` of an agent that waits other than
/// base.agent: one of its root samples comes closer than that to where the agent waits
/// (CrowdState::waiting_at). `scratch` gets the waiting agents near. Never with the rule off.
bool passes_waiting(const GiveWayTuning& t, const CrowdState& s, const ChoiceBase& base, const PlacedCandidate& c,
                    std::vector<int>& scratch);

/// Whether agent `a` waits, as walkers see it from the end of the clip it took (frame `end`) on: it holds
/// ground, has not arrived, and will then have played no moving clip (EscapeTable::moves) for `after`
/// seconds (frames of `dt` seconds). Only where the policy avoids (Policy::avoids); never with the rule off.
bool waits(const GiveWayTuning& t, const Agent& a, std::int64_t end, double dt, bool avoids);
/// The ground walkers keep clear of around an agent waiting on held ground `h`: `reach` metres around
/// its centre, for all time (its box in CrowdState::waiting).
SpaceTimeBox waiting_ground(const GiveWayTuning& t, const Hold& h);

}  // namespace mobb::crowd
