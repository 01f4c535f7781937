// The standing gap (StandingGapTuning; kept by the policies whose agents wander,
// Policy::keeps_standing_gap): no candidate is taken along an escape route whose held ground would come
// within `width` metres, beyond what the disks need, of another agent's held ground - unless
// the agent already stands that close to that ground (the test is then left out: it could never stop
// otherwise). Agents that stop leave room to pass between them instead of packing into knots whose every
// walk is refused and that untangle one slow clip at a time (the longest idle stretches:
// bench/results/log.md). A preference of the choice, not a collision: contacts keep the exact test.
#pragma once
#include <cstdint>

#include "mobb/crowd/tuning.h"
#include "plan/choice_queries.h"
#include "plan/crowd_state.h"

namespace mobb::crowd {

/// Which escape routes of candidate clip `clip`, placed at `base`, would hold ground within the standing
/// gap of another agent's (bit r: route r of EscapeTable::routes), leaving out the held ground the agent
/// already stands that close to (it could not stop otherwise); none with the rule off or when the policy
/// keeps no gap. The others' held ground is asked of `q` (noted as queried).
std::uint32_t crowded_routes(const StandingGapTuning& t, const CrowdState& s, const ChoiceBase& base, int clip,
                             ChoiceQueries& q);

}  // namespace mobb::crowd
