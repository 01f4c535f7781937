#include "mobb/core/obb.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace mobb {

Obb3 extrude(const Obb2& box, double t_min, double t_max) {
    Obb3 out;
    const glm::dvec2 v = box.minor();
    out.center = {box.center, 0.5 * (t_min + t_max)};
    out.axes = glm::dmat3(glm::dvec3(box.axis, 0.0), glm::dvec3(v, 0.0), glm::dvec3(0.0, 0.0, 1.0));
    out.half = {box.half, 0.5 * (t_max - t_min)};
    return out;
}

static glm::dvec3 rotate(const SpaceTimeRigid& m, const glm::dvec3& p) {
    return {m.c * p.x - m.s * p.y, m.s * p.x + m.c * p.y, p.z};
}

Obb2 transformed(const Obb2& box, const SpaceTimeRigid& m) {
    Obb2 out = box;
    const glm::dvec3 c = rotate(m, {box.center, 0.0}) + m.shift;
    out.center = {c.x, c.y};
    const glm::dvec3 a = rotate(m, {box.axis, 0.0});
    out.axis = {a.x, a.y};
    return out;
}

Obb3 transformed(const Obb3& box, const SpaceTimeRigid& m) {
    Obb3 out = box;
    out.center = rotate(m, box.center) + m.shift;
    for (int k = 0; k < 3; ++k) out.axes[k] = rotate(m, box.axes[k]);
    return out;
}

// Projected radius of a box onto a unit axis n.
static double radius2(const Obb2& b, const glm::dvec2& n) {
    return b.half.x * std::abs(glm::dot(b.axis, n)) + b.half.y * std::abs(glm::dot(b.minor(), n));
}

bool overlap(const Obb2& a, const Obb2& b) {
    const glm::dvec2 d = b.center - a.center;
    const glm::dvec2 axes[4] = {a.axis, a.minor(), b.axis, b.minor()};
    for (const glm::dvec2& n : axes)
        if (std::abs(glm::dot(d, n)) > radius2(a, n) + radius2(b, n)) return false;
    return true;
}

bool overlap(const Obb3& a, const Obb3& b) {
    // Ericson, Real-Time Collision Detection 4.4.1: work in a's frame.
    constexpr double guard = 1e-12;  // keeps near-parallel edge axes from false separation
    double r[3][3], ar[3][3];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            r[i][j] = glm::dot(a.axes[i], b.axes[j]);
            ar[i][j] = std::abs(r[i][j]) + guard;
        }
    const glm::dvec3 dw = b.center - a.center;
    const double t[3] = {glm::dot(dw, a.axes[0]), glm::dot(dw, a.axes[1]), glm::dot(dw, a.axes[2])};
    const glm::dvec3& ea = a.half;
    const glm::dvec3& eb = b.half;

    for (int i = 0; i < 3; ++i)
        if (std::abs(t[i]) > ea[i] + eb[0] * ar[i][0] + eb[1] * ar[i][1] + eb[2] * ar[i][2]) return false;
    for (int j = 0; j < 3; ++j)
        if (std::abs(t[0] * r[0][j] + t[1] * r[1][j] + t[2] * r[2][j]) >
            ea[0] * ar[0][j] + ea[1] * ar[1][j] + ea[2] * ar[2][j] + eb[j])
            return false;
    for (int i = 0; i < 3; ++i) {
        const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
        for (int j = 0; j < 3; ++j) {
            const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            const double ra = ea[i1] * ar[i2][j] + ea[i2] * ar[i1][j];
            const double rb = eb[j1] * ar[i][j2] + eb[j2] * ar[i][j1];
            if (std::abs(t[i2] * r[i1][j] - t[i1] * r[i2][j]) > ra + rb) return false;
        }
    }
    return true;
}

}  // namespace mobb
