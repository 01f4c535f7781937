// Paths, placements and the exact collision predicate (paper section 3, equation 1 as pinned by the README).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace mobb {

/// One sample of a clip's path: ground position (x, y) of the root and the radius r of the vertical
/// cylinder that contains every projected joint. Metres.
struct Sample {
    double x = 0, y = 0, r = 0;
};

/// A clip's path: samples i = 0..n-1 at uniform spacing dt (seconds); sample i covers local time
/// [i*dt, (i+1)*dt). Paper section 3.
struct Path {
    double dt = 1.0 / 60.0;
    std::vector<Sample> samples;

    std::size_t size() const { return samples.size(); }
    double duration() const { return dt * double(samples.size()); }
};

/// Throws std::invalid_argument unless dt > 0 and every value is finite with r >= 0.
void validate(const Path& path);

/// Ground speed at each sample, metres per second: the central difference |p_{i+1} - p_{i-1}| / (2 dt),
/// one-sided at the ends; 0 for a one-sample path. The same under any placement (rigid motions keep it).
std::vector<double> sample_speeds(const Path& path);

/// Where and when a clip plays: world position R(theta) p + (x, y) in metres, theta in radians
/// (counter-clockwise seen from above), and sample i covers global time [t0 + i*dt, t0 + (i+1)*dt).
struct Placement {
    double x = 0, y = 0, theta = 0, t0 = 0;
};

/// A placement's rigid 2D part with its rotation evaluated once.
struct Rigid2 {
    double c = 1, s = 0, tx = 0, ty = 0;

    static Rigid2 of(const Placement& p) { return {std::cos(p.theta), std::sin(p.theta), p.x, p.y}; }
    double apply_x(double x, double y) const { return c * x - s * y + tx; }
    double apply_y(double x, double y) const { return s * x + c * y + ty; }
};

/// Rigid motion of space-time (x, y, t): rotation by an angle (radians) about the t axis, then
/// translation. A placement is one: rotation theta, shift (x, y, t0).
struct SpaceTimeRigid {
    double c = 1, s = 0;
    glm::dvec3 shift{0.0};

    static SpaceTimeRigid of(const Placement& p) { return {std::cos(p.theta), std::sin(p.theta), {p.x, p.y, p.t0}}; }
};

/// Global start time of sample k (k may be n: the end of the last sample). Every time comparison in
/// the library goes through this one expression, so trees and the brute-force reference agree exactly.
inline double sample_time(const Placement& p, double dt, std::int64_t k) { return p.t0 + double(k) * dt; }

/// Half-open intervals [a0, a1) and [b0, b1) overlap with positive length.
inline bool times_overlap(double a0, double a1, double b0, double b1) { return a0 < b1 && b0 < a1; }

/// Samples k0..k1 of an m-sample clip placed at p (sample spacing dt) that may overlap global time
/// [s0, s1): the arithmetic window, two samples wider each side (times_overlap() decides); k0 > k1
/// when none.
struct SampleRange {
    std::int64_t k0 = 0, k1 = -1;
};
inline SampleRange aligned_samples(double s0, double s1, const Placement& p, double dt, std::int64_t m) {
    const double lo = std::floor((s0 - p.t0) / dt) - 2, hi = std::ceil((s1 - p.t0) / dt) + 2;
    if (!(hi >= 0 && lo < double(m))) return {};
    return {std::max<std::int64_t>(0, std::int64_t(std::max(lo, -1.0))),
            std::min<std::int64_t>(m - 1, std::int64_t(std::min(hi, double(m))))};
}

/// The one sample test used by every method: placed disks overlap, |p_a - p_b| < r_a + r_b (strict).
inline bool samples_overlap(const Rigid2& ta, const Sample& a, const Rigid2& tb, const Sample& b) {
    const double dx = ta.apply_x(a.x, a.y) - tb.apply_x(b.x, b.y);
    const double dy = ta.apply_y(a.x, a.y) - tb.apply_y(b.x, b.y);
    const double s = a.r + b.r;
    return dx * dx + dy * dy < s * s;
}

/// How far apart the placed disks are, metres: |p_a - p_b| - (r_a + r_b), negative when they overlap
/// (a measure for display; the decision is samples_overlap(), exact without the square root).
inline double samples_gap(const Rigid2& ta, const Sample& a, const Rigid2& tb, const Sample& b) {
    return std::hypot(ta.apply_x(a.x, a.y) - tb.apply_x(b.x, b.y), ta.apply_y(a.x, a.y) - tb.apply_y(b.x, b.y)) -
           (a.r + b.r);
}

}  // namespace mobb
