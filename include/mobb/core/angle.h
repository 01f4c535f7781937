// Angles: the library takes radians (counter-clockwise seen from above), the command line and scene
// files degrees. One pi and one conversion for the whole project.
#pragma once
#include <cmath>

namespace mobb {

inline constexpr double kPi = 3.14159265358979323846;

/// Degrees to radians.
constexpr double radians(double degrees) { return degrees * (kPi / 180.0); }
/// Radians to degrees.
constexpr double degrees(double radians) { return radians * (180.0 / kPi); }

/// The angle a (radians) wrapped into [-pi, pi]: std::remainder(a, 2 pi), to the bit. Angles already in
/// that range (most differences of headings) skip the library call, which the goal policy makes for every
/// clip its look-ahead scores: there remainder's quotient rounds to 0 (a tie at +-pi to even 0 too), so
/// it returns a itself.
inline double wrap_angle(double a) { return std::abs(a) <= kPi ? a : std::remainder(a, 2 * kPi); }

}  // namespace mobb
