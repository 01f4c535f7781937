// NearPoints (src/crowd/policy/near_points.h): the points within reach of a place are among those it
// lists, in ascending order, for crowds of points spread widely or packed, places on and off its grid.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "policy/near_points.h"

namespace mobb::crowd {
namespace {

// The points the goal policy's crowding adds for (x, y), as the plain loop over them all would.
std::vector<std::size_t> within(const std::vector<std::array<double, 2>>& points, double reach, double x, double y) {
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const double dx = x - points[i][0], dy = y - points[i][1];
        if (dx * dx + dy * dy < reach * reach) out.push_back(i);
    }
    return out;
}

TEST(NearPoints, ListsEveryPointWithinReachInOrder) {
    std::mt19937_64 rng(3);
    for (const double spread : {0.5, 6.0, 40.0, 1000.0}) {
        std::uniform_real_distribution<double> u(-spread, spread);
        for (const std::size_t n :
             {std::size_t(0), std::size_t(1), std::size_t(63), std::size_t(64), std::size_t(200)}) {
            std::vector<std::array<double, 2>> points;
            for (std::size_t i = 0; i < n; ++i) points.push_back({100 + u(rng), -50 + u(rng)});
            const double reach = 2.0;
            const NearPoints near(points, reach);
            for (int q = 0; q < 500; ++q) {
                // Places near the points (on cell edges too: a point's own place) and off the grid.
                const double x = q % 5 == 0 && n ? points[std::size_t(q) % n][0] + 2.0 : 100 + 1.5 * u(rng);
                const double y = q % 5 == 0 && n ? points[std::size_t(q) % n][1] : -50 + 1.5 * u(rng);
                std::vector<std::size_t> listed, kept;
                near.near(x, y, [&](std::size_t i) { listed.push_back(i); });
                ASSERT_TRUE(std::is_sorted(listed.begin(), listed.end()));
                for (std::size_t i : listed) {
                    const double dx = x - points[i][0], dy = y - points[i][1];
                    if (dx * dx + dy * dy < reach * reach) kept.push_back(i);
                }
                ASSERT_EQ(kept, within(points, reach, x, y)) << spread << " " << n << " " << x << " " << y;
            }
        }
    }
}

TEST(NearPoints, WithoutAGridListsThemAll) {
    const std::vector<std::array<double, 2>> points{{0, 0}, {5, 5}, {-3, 1}};
    for (const double reach : {0.0, -1.0}) {
        std::vector<std::size_t> listed;
        NearPoints(points, reach).near(100, 100, [&](std::size_t i) { listed.push_back(i); });
        EXPECT_EQ(listed, (std::vector<std::size_t>{0, 1, 2})) << "a reach of " << reach;
    }
}

}  // namespace
}  // namespace mobb::crowd
