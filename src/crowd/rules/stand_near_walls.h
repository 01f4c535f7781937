// Stopping near walls (StandNearWallsTuning): where its agents stop near walls (goal agents:
// Policy::stops_near_walls), held ground keeps room to stand from walls and obstacles - the widest idle
// clip's footprint - not room to turn on the spot, so agents may stop in a door or a corridor; a turn is
// tested against the walls where it is chosen, as every clip is. Starts keep room to turn, and so does
// wanderers' held ground: one that stopped facing a wall with room only to stand could not walk on.
#pragma once
#include "mobb/crowd/policy/policy.h"
#include "mobb/crowd/tuning.h"
#include "plan/escape.h"

namespace mobb::crowd {

/// Metres held ground keeps from walls and obstacles (CrowdState::hold_clearance, tested by meets_solid):
/// EscapeTable::stand_clearance with the rule on where the policy's agents stop near walls, else
/// turn_clearance.
inline double hold_clearance(const StandNearWallsTuning& t, const Policy& policy, const EscapeTable& escapes) {
    return t.on && policy.stops_near_walls() ? escapes.stand_clearance : escapes.turn_clearance;
}

}  // namespace mobb::crowd
