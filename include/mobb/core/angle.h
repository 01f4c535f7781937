// Angles: the library takes radians (counter-clockwise seen from above), the command line and scene
// files degrees. One pi and one conversion for the whole project.
#pragma once

namespace mobb {

inline constexpr double kPi = 3.14159265358979323846;

/// Degrees to radians.
constexpr double radians(double degrees) { return degrees * (kPi / 180.0); }
/// Radians to degrees.
constexpr double degrees(double radians) { return radians * (180.0 / kPi); }

}  // namespace mobb
