// Separating-axis tests against dense point sampling: a sound check both ways.
//  - If SAT says separated, no point of a's grid lies in b.
//  - If SAT says the boxes shrunk by delta still overlap, a grid finer than delta must find a common point.
#include <gtest/gtest.h>

#include <random>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "mobb/core/obb.h"

namespace mobb {
namespace {

constexpr double kDelta = 0.06;

bool inside(const Obb2& b, const glm::dvec2& p, double tol = 1e-12) {
    const glm::dvec2 d = p - b.center;
    return std::abs(glm::dot(d, b.axis)) <= b.half.x + tol && std::abs(glm::dot(d, b.minor())) <= b.half.y + tol;
}

bool inside(const Obb3& b, const glm::dvec3& p, double tol = 1e-12) {
    const glm::dvec3 d = p - b.center;
    for (int k = 0; k < 3; ++k)
        if (std::abs(glm::dot(d, b.axes[k])) > b.half[k] + tol) return false;
    return true;
}

// Grid points of box a with spacing h along its axes, visiting until f returns true.
template <class F>
bool any_grid_point(const Obb2& a, double h, F f) {
    const int nx = int(2 * a.half.x / h) + 1, ny = int(2 * a.half.y / h) + 1;
    for (int i = 0; i <= nx; ++i)
        for (int j = 0; j <= ny; ++j) {
            const double u = -a.half.x + 2 * a.half.x * i / nx, v = -a.half.y + 2 * a.half.y * j / ny;
            if (f(a.center + u * a.axis + v * a.minor())) return true;
        }
    return false;
}

template <class F>
bool any_grid_point(const Obb3& a, double h, F f) {
    int n[3];
    for (int k = 0; k < 3; ++k) n[k] = int(2 * a.half[k] / h) + 1;
    for (int i = 0; i <= n[0]; ++i)
        for (int j = 0; j <= n[1]; ++j)
            for (int l = 0; l <= n[2]; ++l) {
                const double c[3] = {-a.half[0] + 2 * a.half[0] * i / n[0], -a.half[1] + 2 * a.half[1] * j / n[1],
                                     -a.half[2] + 2 * a.half[2] * l / n[2]};
                if (f(a.center + c[0] * a.axes[0] + c[1] * a.axes[1] + c[2] * a.axes[2])) return true;
            }
    return false;
}

Obb2 random_obb2(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Obb2 b;
    const double a = u(rng) * 6.283185307179586;
    b.axis = {std::cos(a), std::sin(a)};
    b.center = {3 * u(rng), 3 * u(rng)};
    b.half = {0.1 + u(rng), 0.1 + u(rng)};
    return b;
}

Obb3 random_obb3(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    glm::dvec3 axis = glm::normalize(glm::dvec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5));
    const glm::dmat3 rot(glm::rotate(glm::dmat4(1.0), u(rng) * 6.283185307179586, axis));
    Obb3 b;
    b.axes = rot;
    b.center = {2 * u(rng), 2 * u(rng), 2 * u(rng)};
    b.half = {0.15 + 0.6 * u(rng), 0.15 + 0.6 * u(rng), 0.15 + 0.6 * u(rng)};
    return b;
}

template <class Box>
Box shrunk(Box b) {
    b.half -= kDelta;
    return b;
}

TEST(Obb2Test, AgreesWithDensePointSampling) {
    std::mt19937_64 rng(1);
    int overlapping = 0, separated = 0;
    for (int t = 0; t < 4000; ++t) {
        const Obb2 a = random_obb2(rng), b = random_obb2(rng);
        const bool sat = overlap(a, b);
        EXPECT_EQ(sat, overlap(b, a));
        if (!sat) {
            ++separated;
            EXPECT_FALSE(any_grid_point(a, 0.01, [&](glm::dvec2 p) { return inside(b, p); })) << t;
        } else if (overlap(shrunk(a), shrunk(b))) {
            ++overlapping;
            EXPECT_TRUE(any_grid_point(a, kDelta, [&](glm::dvec2 p) { return inside(b, p); })) << t;
        }
    }
    EXPECT_GT(overlapping, 400);
    EXPECT_GT(separated, 400);
}

TEST(Obb3Test, AgreesWithDensePointSampling) {
    std::mt19937_64 rng(2);
    int overlapping = 0, separated = 0;
    for (int t = 0; t < 1500; ++t) {
        const Obb3 a = random_obb3(rng), b = random_obb3(rng);
        const bool sat = overlap(a, b);
        EXPECT_EQ(sat, overlap(b, a));
        if (!sat) {
            ++separated;
            EXPECT_FALSE(any_grid_point(a, 0.03, [&](glm::dvec3 p) { return inside(b, p); })) << t;
        } else if (overlap(shrunk(a), shrunk(b))) {
            ++overlapping;
            EXPECT_TRUE(any_grid_point(a, kDelta, [&](glm::dvec3 p) { return inside(b, p); })) << t;
        }
    }
    EXPECT_GT(overlapping, 100);
    EXPECT_GT(separated, 100);
}

// Edge-edge axes matter: two bars with diamond cross-sections (rolled 45 degrees about their long
// axes), crossed at right angles and offset in z, are separated only by the cross product of their
// long axes; no face normal separates them.
TEST(Obb3Test, FindsEdgeEdgeSeparatingAxis) {
    const glm::dmat3 roll_x(glm::rotate(glm::dmat4(1.0), 0.25 * 3.141592653589793, glm::dvec3(1, 0, 0)));
    const glm::dmat3 roll_y(glm::rotate(glm::dmat4(1.0), 0.25 * 3.141592653589793, glm::dvec3(0, 1, 0)));
    Obb3 a, b;
    a.axes = roll_x;  // long along x
    a.half = {2.0, 0.1, 0.1};
    b.axes = roll_y;  // long along y
    b.half = {0.1, 2.0, 0.1};
    const double reach = 0.2 * std::sqrt(0.5);  // each bar's half depth along z
    b.center = {0.0, 0.0, 2 * reach + 0.01};
    EXPECT_FALSE(overlap(a, b));
    b.center = {0.0, 0.0, 2 * reach - 0.01};
    EXPECT_TRUE(overlap(a, b));
}

TEST(Obb3Test, ExtrudedBoxesMatch2DTestWhenTimesOverlap) {
    std::mt19937_64 rng(3);
    for (int t = 0; t < 2000; ++t) {
        const Obb2 a = random_obb2(rng), b = random_obb2(rng);
        EXPECT_EQ(overlap(a, b), overlap(extrude(a, 0, 1), extrude(b, 0.5, 2))) << t;
        EXPECT_FALSE(overlap(extrude(a, 0, 1), extrude(b, 1.5, 2))) << t;
    }
}

TEST(ObbTest, TransformedBoxesKeepPointMembership) {
    std::mt19937_64 rng(4);
    const SpaceTimeRigid m{std::cos(0.7), std::sin(0.7), {3.0, -1.0, 2.5}};
    for (int t = 0; t < 200; ++t) {
        const Obb3 b = random_obb3(rng);
        const Obb3 moved = transformed(b, m);
        const glm::dvec3 p = b.center + 0.9 * b.half.x * b.axes[0];
        const glm::dvec3 q{m.c * p.x - m.s * p.y + m.shift.x, m.s * p.x + m.c * p.y + m.shift.y, p.z + m.shift.z};
        EXPECT_TRUE(inside(moved, q, 1e-9));
        const Obb2 b2 = random_obb2(rng);
        const Obb2 m2 = transformed(b2, m);
        const glm::dvec2 p2 = b2.center + 0.9 * b2.half.y * b2.minor();
        EXPECT_TRUE(inside(m2, {m.c * p2.x - m.s * p2.y + m.shift.x, m.s * p2.x + m.c * p2.y + m.shift.y}, 1e-9));
    }
}

}  // namespace
}  // namespace mobb
