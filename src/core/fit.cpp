#include "mobb/core/fit.h"
#include "mobb/core/assert.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

namespace mobb {

namespace {

// Below this many metres first and last sample "coincide" and the chord gives no direction.
constexpr double kCoincident = 1e-6;

struct Interval {
    double lo = INFINITY, hi = -INFINITY;
    void add(double a, double b) {
        lo = std::min(lo, a);
        hi = std::max(hi, b);
    }
    double mid() const { return 0.5 * (lo + hi); }
    double half() const { return 0.5 * (hi - lo); }
};

// Projection of sample cylinder (base centre (x, y, t), radius r, height dt) onto unit axis n.
Interval project(const glm::dvec3& n, const Sample& s, double t, double dt) {
    const double c = n.x * s.x + n.y * s.y + n.z * t;
    const double reach = s.r * std::hypot(n.x, n.y);
    Interval out;
    out.add(c - reach + std::min(0.0, dt * n.z), c + reach + std::max(0.0, dt * n.z));
    return out;
}

}  // namespace

AxisFit parse_axis_fit(const std::string& name) {
    if (name == "chord") return AxisFit::Chord;
    if (name == "pca") return AxisFit::Pca;
    throw std::invalid_argument("unknown axis fit '" + name + "' (chord, pca)");
}

double fit_margin(const Path& path) {
    double extent = path.duration();
    for (const Sample& s : path.samples) extent = std::max({extent, std::abs(s.x) + s.r, std::abs(s.y) + s.r});
    return 1e-9 * (1.0 + extent);
}

glm::dvec2 principal_axis(const Path& path, std::size_t first, std::size_t end) {
    glm::dvec2 mean(0.0);
    for (std::size_t i = first; i < end; ++i) mean += glm::dvec2(path.samples[i].x, path.samples[i].y);
    mean /= double(end - first);
    double cxx = 0, cyy = 0, cxy = 0;
    for (std::size_t i = first; i < end; ++i) {
        const glm::dvec2 d = glm::dvec2(path.samples[i].x, path.samples[i].y) - mean;
        cxx += d.x * d.x;
        cyy += d.y * d.y;
        cxy += d.x * d.y;
    }
    const double angle = 0.5 * std::atan2(2.0 * cxy, cxx - cyy);  // (1, 0) when all coincide
    return {std::cos(angle), std::sin(angle)};
}

Obb2 fit_obb2(const Path& path, std::size_t first, std::size_t end, AxisFit fit) {
    MOBB_ASSERT(first < end && end <= path.samples.size());
    const Sample& a = path.samples[first];
    const Sample& b = path.samples[end - 1];
    glm::dvec2 u(b.x - a.x, b.y - a.y);
    const double len = glm::length(u);
    u = (fit == AxisFit::Chord && len > kCoincident) ? u / len : principal_axis(path, first, end);

    Obb2 box;
    box.axis = u;
    const glm::dvec2 v = box.minor();
    Interval iu, iv;
    for (std::size_t i = first; i < end; ++i) {
        const Sample& s = path.samples[i];
        const double pu = u.x * s.x + u.y * s.y, pv = v.x * s.x + v.y * s.y;
        iu.add(pu - s.r, pu + s.r);
        iv.add(pv - s.r, pv + s.r);
    }
    const double margin = fit_margin(path);
    box.center = u * iu.mid() + v * iv.mid();
    box.half = {iu.half() + margin, iv.half() + margin};
    return box;
}

bool fit_obb3(const Path& path, std::size_t first, std::size_t end, Obb3& box) {
    MOBB_ASSERT(first < end && end <= path.samples.size());
    const Sample& a = path.samples[first];
    const Sample& b = path.samples[end - 1];
    glm::dvec3 a0(b.x - a.x, b.y - a.y, double(end - 1 - first) * path.dt);
    if (std::hypot(a0.x, a0.y) <= kCoincident) return false;
    a0 = glm::normalize(a0);
    const glm::dvec3 a1 = glm::normalize(glm::dvec3(-a0.y, a0.x, 0.0));
    const glm::dvec3 a2 = glm::cross(a0, a1);

    const glm::dvec3 axes[3] = {a0, a1, a2};
    Interval range[3];
    for (std::size_t i = first; i < end; ++i)
        for (int k = 0; k < 3; ++k) {
            const Interval p = project(axes[k], path.samples[i], double(i) * path.dt, path.dt);
            range[k].add(p.lo, p.hi);
        }
    const double margin = fit_margin(path);
    box.axes = glm::dmat3(a0, a1, a2);
    box.center = a0 * range[0].mid() + a1 * range[1].mid() + a2 * range[2].mid();
    box.half = {range[0].half() + margin, range[1].half() + margin, range[2].half() + margin};
    return true;
}

bool contains(const Obb2& box, const Sample& s, double tol) {
    const glm::dvec2 d = glm::dvec2(s.x, s.y) - box.center;
    return std::abs(glm::dot(d, box.axis)) + s.r <= box.half.x + tol &&
           std::abs(glm::dot(d, box.minor())) + s.r <= box.half.y + tol;
}

bool contains(const Obb3& box, const Sample& s, double t, double dt, double tol) {
    for (int k = 0; k < 3; ++k) {
        const glm::dvec3& n = box.axes[k];
        const Interval p = project(n, s, t, dt);
        const double c = glm::dot(n, box.center);
        if (p.lo < c - box.half[k] - tol || p.hi > c + box.half[k] + tol) return false;
    }
    return true;
}

}  // namespace mobb
