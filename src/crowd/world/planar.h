// Distances in the ground plane for the hot loops (metrics per agent and frame, the navigation fields).
#pragma once
#include <cmath>

namespace mobb::crowd {

/// sqrt(dx^2 + dy^2), metres. Not std::hypot: glibc's is correctly rounded for any magnitude and several
/// times slower, and the crowd's coordinates (metres, at most kilometres) are far from overflow.
inline double planar_distance(double dx, double dy) { return std::sqrt(dx * dx + dy * dy); }

}  // namespace mobb::crowd
