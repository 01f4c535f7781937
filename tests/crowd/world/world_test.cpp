// The obstacle test (disk_overlaps) against brute force: the polygon sampled densely - its edges and
// its interior on a fine grid - and the disk's centre's nearest sample.
#include <gtest/gtest.h>

#include <cmath>

#include "mobb/core/angle.h"
#include "mobb/crowd/world/world.h"
#include "mobb/util/random.h"

namespace mobb::crowd {
namespace {

constexpr double kStep = 0.01;  // metres between the dense samples

// Even-odd inside test, the test's own.
bool contains(const Polygon& p, double x, double y) {
    bool in = false;
    const auto& v = p.vertices;
    for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++)
        if ((v[i][1] > y) != (v[j][1] > y) && x < (v[j][0] - v[i][0]) * (y - v[i][1]) / (v[j][1] - v[i][1]) + v[i][0])
            in = !in;
    return in;
}

std::vector<std::array<double, 2>> dense(const Polygon& p) {
    std::vector<std::array<double, 2>> out;
    const auto& v = p.vertices;
    for (std::size_t i = 0; i < v.size(); ++i) {
        const auto& a = v[i];
        const auto& b = v[(i + 1) % v.size()];
        const int n = std::max(1, int(std::hypot(b[0] - a[0], b[1] - a[1]) / kStep));
        for (int k = 0; k <= n; ++k) out.push_back({a[0] + (b[0] - a[0]) * k / n, a[1] + (b[1] - a[1]) * k / n});
    }
    if (v.size() >= 3) {
        const auto b = bounds(p);
        for (double x = b[0]; x <= b[2]; x += kStep)
            for (double y = b[1]; y <= b[3]; y += kStep)
                if (contains(p, x, y)) out.push_back({x, y});
    }
    return out;
}

// A star-shaped polygon around (cx, cy): concave in general.
Polygon star(util::Random& rng, double cx, double cy) {
    Polygon p;
    const int n = 3 + rng.below(7);
    for (int k = 0; k < n; ++k) {
        const double a = 2 * kPi * (k + rng.uniform(0.1, 0.9)) / n, r = rng.uniform(0.3, 2.0);
        p.vertices.push_back({cx + r * std::cos(a), cy + r * std::sin(a)});
    }
    return p;
}

void check_against_dense(const Polygon& p, util::Random& rng, int disks, int& overlapping, int& clear) {
    const auto pts = dense(p);
    const auto b = bounds(p);
    for (int d = 0; d < disks; ++d) {
        const double x = rng.uniform(b[0] - 1.5, b[2] + 1.5), y = rng.uniform(b[1] - 1.5, b[3] + 1.5);
        const double r = rng.uniform(0.05, 1.0);
        double nearest = 1e300;
        for (const auto& q : pts) nearest = std::min(nearest, std::hypot(q[0] - x, q[1] - y));
        // Every point of the polygon is within kStep of a dense sample.
        if (nearest < r) {
            EXPECT_TRUE(disk_overlaps(p, x, y, r)) << x << ", " << y << ", r " << r;
            ++overlapping;
        } else if (nearest - kStep > r) {
            EXPECT_FALSE(disk_overlaps(p, x, y, r)) << x << ", " << y << ", r " << r;
            ++clear;
        }
    }
}

TEST(World, DiskOverlapsPolygonsAsDenseSamplingSays) {
    util::Random rng(3);
    int overlapping = 0, clear = 0;
    for (int k = 0; k < 12; ++k) check_against_dense(star(rng, 5, 5), rng, 150, overlapping, clear);
    check_against_dense(Polygon::rectangle(1, 2, 4, 2.5), rng, 300, overlapping, clear);
    // A rotated rectangle takes the general path, a segment is a thin wall.
    check_against_dense(Polygon{{{0, 0}, {2, 1}, {1.5, 2}, {-0.5, 1}}}, rng, 300, overlapping, clear);
    check_against_dense(Polygon{{{0, 0}, {3, 1}}}, rng, 300, overlapping, clear);
    EXPECT_GT(overlapping, 500);
    EXPECT_GT(clear, 500);
}

TEST(World, TouchingIsNoOverlapAndInsideIs) {
    const Polygon box = Polygon::rectangle(0, 0, 2, 1);
    EXPECT_FALSE(disk_overlaps(box, 3, 0.5, 1.0));  // touches the right edge
    EXPECT_TRUE(disk_overlaps(box, 3, 0.5, 1.0 + 1e-12));
    EXPECT_TRUE(disk_overlaps(box, 1, 0.5, 0.01));  // centre inside
    const Polygon tri{{{0, 0}, {2, 0}, {0, 2}}};
    EXPECT_TRUE(disk_overlaps(tri, 0.5, 0.5, 1e-6));
    EXPECT_FALSE(disk_overlaps(tri, 2, 2, std::sqrt(2.0) - 1e-9));
    EXPECT_TRUE(disk_overlaps(tri, 2, 2, std::sqrt(2.0) + 1e-9));
}

TEST(World, PathHitsTestsEverySampleFromTheFirstOn) {
    Path path;
    path.dt = 0.1;
    for (int i = 0; i < 20; ++i) path.samples.push_back({0.1 * i, 0, 0.2});
    const Polygon pillar = Polygon::rectangle(1.5, -0.5, 2.5, 0.5);
    // Placed at x = 0 the samples reach 1.9 + 0.2: into the pillar from sample 14 (1.4 + 0.2 > 1.5) on.
    const Placement origin{0, 0, 0, 0}, turned{0, 0, kPi, 0}, beside{0, 1.0, 0, 0};
    EXPECT_TRUE(path_hits(path, origin, pillar));
    EXPECT_TRUE(path_hits(path, origin, pillar, 14));
    EXPECT_FALSE(path_hits(path, origin, pillar, 20));
    EXPECT_FALSE(path_hits(path, turned, pillar));  // turned around, it walks away
    EXPECT_FALSE(path_hits(path, beside, pillar));  // 0.5 m beside it, r 0.2
    EXPECT_TRUE(path_hits(path, Rigid2::of(origin), pillar, 14));
    EXPECT_FALSE(path_hits(path, Rigid2::of(turned), pillar));
}

TEST(World, WallsAreSolidsOutsideTheRectangle) {
    World w;
    w.x1 = 10;
    w.y1 = 8;
    w.obstacles.push_back(Polygon::rectangle(4, 4, 5, 5));
    const std::vector<Polygon> solids = w.solids();
    ASSERT_EQ(solids.size(), 5u);
    auto any = [&](double x, double y, double r) {
        for (const Polygon& p : solids)
            if (disk_overlaps(p, x, y, r)) return true;
        return false;
    };
    EXPECT_FALSE(any(0.3, 0.3, 0.3));  // in the corner, touching both walls
    EXPECT_TRUE(any(0.3, 0.3, 0.31));
    EXPECT_TRUE(any(9.9, 4, 0.2));
    EXPECT_TRUE(any(4.5, 3.8, 0.3));
    EXPECT_FALSE(any(2, 2, 1));
    w.walls = false;
    EXPECT_EQ(w.solids().size(), 1u);
}

}  // namespace
}  // namespace mobb::crowd
