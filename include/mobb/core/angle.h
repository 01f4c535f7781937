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

/// The angle a (radians) wrapped into [-pi, pi]: std::remainder(a, 2 pi), to the bit, without the library
/// call (which the goal policy makes for every clip its look-ahead scores) where |a| < 2 pi. Up to pi,
/// remainder's quotient rounds to 0 (a tie at +-pi to even 0 too), so it returns a itself; beyond, to +-1,
/// and a -+ 2 pi is exact (Sterbenz: a is within a factor 2 of 2 pi) and not 0, whose sign would differ.
inline double wrap_angle(double a) {
    if (std::abs(a) <= kPi) return a;
    if (std::abs(a) < 2 * kPi) return a - std::copysign(2 * kPi, a);
    return std::remainder(a, 2 * kPi);
}

}  // namespace mobb
