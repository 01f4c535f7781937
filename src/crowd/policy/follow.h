// Following (CrowdTuning::follow; rules/follow.h): whom an agent follows. Shared by the look-ahead, which
// plans past a leader's reservations, and the goal policy, which counts no crowding for a leader.
#pragma once
#include <array>
#include <cmath>

#include "mobb/core/angle.h"

namespace mobb::crowd {

/// Whether an agent at `from` wanting to go `way` (radians) follows one at `at` facing `facing`
/// (radians): the other is ahead, within `cone` radians of the way, and faces within `cone` of it.
inline bool follows(double way, const std::array<double, 2>& from, const std::array<double, 2>& at, double facing,
                    double cone) {
    if (!(std::abs(wrap_angle(facing - way)) <= cone)) return false;  // before the atan2
    const double bearing = std::atan2(at[1] - from[1], at[0] - from[0]);
    return std::abs(wrap_angle(bearing - way)) <= cone;
}

}  // namespace mobb::crowd
