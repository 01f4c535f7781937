#include <gtest/gtest.h>

#include <random>

#include <glm/geometric.hpp>

#include "mobb/core/fit.h"
#include "random_paths.h"

namespace mobb {
namespace {

void expect_contains_all(const Path& p, std::size_t first, std::size_t end) {
    const Obb2 box2 = fit_obb2(p, first, end);
    const Obb2 pca = fit_obb2(p, first, end, AxisFit::Pca);
    Obb3 box3;
    const bool is3 = fit_obb3(p, first, end, box3);
    for (std::size_t i = first; i < end; ++i) {
        EXPECT_TRUE(contains(box2, p.samples[i])) << i;
        EXPECT_TRUE(contains(pca, p.samples[i])) << i;
        EXPECT_TRUE(contains(extrude(box2, double(first) * p.dt, double(end) * p.dt), p.samples[i], double(i) * p.dt,
                             p.dt, 1e-12));
        if (is3) {
            EXPECT_TRUE(contains(box3, p.samples[i], double(i) * p.dt, p.dt)) << i;
        }
    }
}

TEST(FitTest, BoxesContainEverySampleCylinder) {
    std::mt19937_64 rng(7);
    for (int t = 0; t < 50; ++t) {
        const Path p = test::random_walk(rng, 1 + t * 13);
        expect_contains_all(p, 0, p.size());
        expect_contains_all(p, p.size() / 3, p.size() / 3 + 1);
    }
}

TEST(FitTest, BoxesAreTightOnTheirOwnAxes) {
    std::mt19937_64 rng(8);
    const Path p = test::random_walk(rng, 200);
    const Obb2 box = fit_obb2(p, 0, p.size());
    // Some disk touches each side of the box (to within the safety margin).
    const double margin = fit_margin(p);
    for (int side = 0; side < 4; ++side) {
        const glm::dvec2 n = (side % 2 ? box.minor() : box.axis) * (side < 2 ? 1.0 : -1.0);
        const double half = side % 2 ? box.half.y : box.half.x;
        double reach = -1e9;
        for (const Sample& s : p.samples) reach = std::max(reach, glm::dot(glm::dvec2(s.x, s.y) - box.center, n) + s.r);
        EXPECT_NEAR(reach, half - margin, 1e-9);
    }
}

TEST(FitTest, MobbMajorAxisIsTheChord) {
    Path p;
    p.samples = {{0, 0, 0.1}, {1, 0.5, 0.1}, {3, 4, 0.1}};
    const Obb2 box = fit_obb2(p, 0, 3);
    EXPECT_NEAR(box.axis.x, 0.6, 1e-12);
    EXPECT_NEAR(box.axis.y, 0.8, 1e-12);
}

TEST(FitTest, CoincidentEndsFallBackToPrincipalAxis) {
    Path p;
    p.samples = {{0, 0, 0.1}, {2, 2, 0.1}, {4, 4, 0.1}, {2, 2, 0.1}, {0, 0, 0.1}};
    const Obb2 box = fit_obb2(p, 0, p.size());
    EXPECT_NEAR(std::abs(box.axis.x), std::sqrt(0.5), 1e-9);
    EXPECT_NEAR(std::abs(box.axis.y), std::sqrt(0.5), 1e-9);
    expect_contains_all(p, 0, p.size());
}

TEST(FitTest, DegeneratePaths) {
    expect_contains_all(test::standing_still(1), 0, 1);
    expect_contains_all(test::standing_still(40), 0, 40);
    expect_contains_all(test::circle(90), 0, 90);
    Obb3 box;
    EXPECT_FALSE(fit_obb3(test::standing_still(40), 0, 40, box)) << "time-parallel UMOBB axis becomes a 2D node";
    EXPECT_FALSE(fit_obb3(test::circle(90), 0, 90, box));
    const Obb2 still = fit_obb2(test::standing_still(40, 0.3), 0, 40);
    EXPECT_NEAR(still.half.x, 0.3, 1e-6);
    EXPECT_NEAR(still.half.y, 0.3, 1e-6);
}

TEST(FitTest, UmobbAxesFollowSpaceTimeChord) {
    Path p;
    p.dt = 0.5;
    p.samples = {{0, 0, 0.1}, {0.5, 0, 0.1}, {1, 0, 0.1}};
    Obb3 box;
    ASSERT_TRUE(fit_obb3(p, 0, 3, box));
    EXPECT_NEAR(box.axes[0].x, std::sqrt(0.5), 1e-12);  // (1, 0, 1) / sqrt 2: 1 m over 1 s
    EXPECT_NEAR(box.axes[0].z, std::sqrt(0.5), 1e-12);
    EXPECT_NEAR(box.axes[1].z, 0.0, 1e-12);
    EXPECT_NEAR(glm::dot(glm::cross(box.axes[0], box.axes[1]), box.axes[2]), 1.0, 1e-12);
    expect_contains_all(p, 0, 3);
}

}  // namespace
}  // namespace mobb
