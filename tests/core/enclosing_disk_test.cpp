// The smallest enclosing disk against the brute force over every disk two or three of the points define.
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "mobb/core/enclosing_disk.h"

namespace mobb {
namespace {

double farthest(const Sample& d, const std::vector<glm::dvec2>& p) {
    double r = 0;
    for (const glm::dvec2& q : p) r = std::max(r, std::hypot(q.x - d.x, q.y - d.y));
    return r;
}

// The smallest disk holding every point is one with two points as its diameter or three on its circle.
double brute_radius(const std::vector<glm::dvec2>& p) {
    double best = INFINITY;
    auto consider = [&](double x, double y) { best = std::min(best, farthest({x, y, 0}, p)); };
    for (std::size_t i = 0; i < p.size(); ++i) {
        consider(p[i].x, p[i].y);
        for (std::size_t j = i + 1; j < p.size(); ++j) {
            consider((p[i].x + p[j].x) / 2, (p[i].y + p[j].y) / 2);
            for (std::size_t k = j + 1; k < p.size(); ++k) {
                const glm::dvec2 a = p[i], b = p[j], c = p[k];
                const double d = 2 * (a.x * (b.y - c.y) + b.x * (c.y - a.y) + c.x * (a.y - b.y));
                if (std::abs(d) < 1e-12) continue;
                const double a2 = a.x * a.x + a.y * a.y, b2 = b.x * b.x + b.y * b.y, c2 = c.x * c.x + c.y * c.y;
                consider((a2 * (b.y - c.y) + b2 * (c.y - a.y) + c2 * (a.y - b.y)) / d,
                         (a2 * (c.x - b.x) + b2 * (a.x - c.x) + c2 * (b.x - a.x)) / d);
            }
        }
    }
    return best;
}

TEST(EnclosingDisk, IsTheSmallestDiskHoldingEveryPoint) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int trial = 0; trial < 300; ++trial) {
        std::vector<glm::dvec2> p(std::size_t(1 + trial % 14));
        for (glm::dvec2& q : p) q = {u(rng) * 0.5 + 3, u(rng) * (trial % 3 ? 0.5 : 0.05) - 2};  // some flat sets
        const Sample d = enclosing_disk(p);
        SCOPED_TRACE(trial);
        EXPECT_LE(farthest(d, p), d.r) << "every point within the radius, as computed";
        EXPECT_NEAR(d.r, brute_radius(p), 1e-9);
    }
}

TEST(EnclosingDisk, DegenerateSets) {
    EXPECT_EQ(enclosing_disk({}).r, 0.0);
    const Sample one = enclosing_disk({{2, 3}});
    EXPECT_EQ(one.x, 2.0);
    EXPECT_EQ(one.y, 3.0);
    EXPECT_EQ(one.r, 0.0);
    const Sample same = enclosing_disk({{1, 1}, {1, 1}, {1, 1}});
    EXPECT_EQ(same.r, 0.0);
    const Sample line = enclosing_disk({{0, 0}, {1, 0}, {2, 0}, {3, 0}, {0.5, 0}});  // collinear
    EXPECT_NEAR(line.x, 1.5, 1e-12);
    EXPECT_NEAR(line.y, 0.0, 1e-12);
    EXPECT_NEAR(line.r, 1.5, 1e-12);
    // An obtuse triangle: the longest side's diameter, not the circumcircle.
    const Sample obtuse = enclosing_disk({{-1, 0}, {1, 0}, {0, 0.2}});
    EXPECT_NEAR(obtuse.x, 0.0, 1e-12);
    EXPECT_NEAR(obtuse.y, 0.0, 1e-12);
    EXPECT_NEAR(obtuse.r, 1.0, 1e-12);
    // An equilateral triangle: the circumcircle.
    const Sample eq = enclosing_disk({{1, 0}, {-0.5, std::sqrt(3) / 2}, {-0.5, -std::sqrt(3) / 2}});
    EXPECT_NEAR(eq.r, 1.0, 1e-12);
}

}  // namespace
}  // namespace mobb
