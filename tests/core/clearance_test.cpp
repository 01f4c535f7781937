// Clearance over time against the collision predicate: negative somewhere exactly when brute force
// finds a collision, and the exact margin where it can be worked out by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "mobb/core/brute.h"
#include "mobb/core/clearance.h"
#include "random_paths.h"

namespace mobb {
namespace {

double least_gap(const std::vector<ClearanceSample>& c) {
    double g = 1e300;
    for (const ClearanceSample& s : c) g = std::min(g, s.gap);
    return g;
}

TEST(Clearance, NegativeExactlyWhenBruteForceCollides) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int hits = 0, misses = 0;
    for (int k = 0; k < 400; ++k) {
        const Path a = test::random_walk(rng, 60 + int(rng() % 200)), b = test::random_walk(rng, 60 + int(rng() % 200));
        const Placement pa{2 * u(rng), 2 * u(rng), 3 * u(rng), u(rng)}, pb{2 * u(rng), 2 * u(rng), 3 * u(rng), u(rng)};
        const std::vector<ClearanceSample> c = clearance(a, pa, b, pb);
        const bool collide = collide_brute(a, pa, b, pb);
        EXPECT_EQ(!c.empty() && least_gap(c) < 0, collide) << "pair " << k;
        (collide ? hits : misses) += 1;
        for (std::size_t i = 1; i < c.size(); ++i) EXPECT_LT(c[i - 1].t, c[i].t);
    }
    EXPECT_GT(hits, 40);
    EXPECT_GT(misses, 40);
}

TEST(Clearance, StandingCharactersKeepTheirDistanceMinusRadii) {
    const Path a = test::standing_still(30, 0.3), b = test::standing_still(30, 0.2);
    // Both stand at (1, -2) in their clip frame; b is placed 2 m further along x and starts 0.25 s later.
    const std::vector<ClearanceSample> c = clearance(a, {0, 0, 0, 0}, b, {2, 0, 0, 0.25});
    ASSERT_FALSE(c.empty());
    for (const ClearanceSample& s : c) EXPECT_NEAR(s.gap, 2.0 - 0.5, 1e-12);
    EXPECT_GE(c.front().t + a.dt, 0.25);  // no entry before b starts
}

TEST(Clearance, ClipsApartInTimeHaveNone) {
    const Path a = test::standing_still(30), b = test::standing_still(30);
    EXPECT_TRUE(clearance(a, {}, b, {0, 0, 0, 30 * a.dt}).empty());  // b starts as a ends
}

/// nearest_clearance() per sample equals the least clearance() gap over every other clip, for random
/// crowds of clips with overlapping and disjoint time ranges; +infinity where no clip overlaps in time.
TEST(NearestClearance, LeastOfThePairwiseClearances) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int round = 0; round < 20; ++round) {
        const int n = 2 + int(rng() % 4);
        std::vector<Path> paths;
        std::vector<Placement> places;
        for (int c = 0; c < n; ++c) {
            paths.push_back(test::random_walk(rng, 30 + int(rng() % 120)));
            places.push_back({3 * u(rng), 3 * u(rng), 3 * u(rng), 2 * u(rng)});
        }
        std::vector<const Path*> ptrs;
        for (const Path& p : paths) ptrs.push_back(&p);
        const auto nearest = nearest_clearance(ptrs, places);
        ASSERT_EQ(nearest.size(), paths.size());
        for (int c = 0; c < n; ++c) {
            std::vector<double> expected(paths[std::size_t(c)].size(), std::numeric_limits<double>::infinity());
            for (int d = 0; d < n; ++d) {
                if (d == c) continue;
                for (const ClearanceSample& s : clearance(paths[std::size_t(c)], places[std::size_t(c)],
                                                          paths[std::size_t(d)], places[std::size_t(d)]))
                    expected[std::size_t(s.i)] = std::min(expected[std::size_t(s.i)], s.gap);
            }
            ASSERT_EQ(nearest[std::size_t(c)].size(), expected.size());
            for (std::size_t i = 0; i < expected.size(); ++i)
                EXPECT_EQ(nearest[std::size_t(c)][i], expected[i])
                    << "round " << round << " clip " << c << " sample " << i;
        }
    }
}

TEST(NearestClearance, AloneInTimeIsInfinite) {
    const Path a = test::standing_still(30), b = test::standing_still(30);
    const auto g = nearest_clearance({&a, &b}, {{}, {0, 0, 0, 30 * a.dt}});
    for (const auto& clip : g)
        for (double x : clip) EXPECT_TRUE(std::isinf(x) && x > 0);
    const auto one = nearest_clearance({&a}, {{}});
    ASSERT_EQ(one.size(), 1u);
    EXPECT_TRUE(std::isinf(one[0][0]));
}

}  // namespace
}  // namespace mobb
