// wrap_angle: std::remainder(a, 2 pi) to the bit, its shortcuts included (the turns the goal policy scores).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "mobb/core/angle.h"

namespace mobb {
namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(WrapAngle, IsRemainderToTheBit) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> turns(-3, 3);
    for (int i = 0; i < 200000; ++i) {
        const double a = turns(rng) * 2 * kPi;
        ASSERT_TRUE(same_bits(wrap_angle(a), std::remainder(a, 2 * kPi))) << a;
    }
    // The ends of each shortcut, and a step either side of them.
    for (double edge : {0.0, kPi, 2 * kPi, 3 * kPi, 4 * kPi})
        for (double sign : {1.0, -1.0}) {
            const double e = sign * edge;
            for (double a : {std::nextafter(e, -10.0), e, std::nextafter(e, 10.0)})
                EXPECT_TRUE(same_bits(wrap_angle(a), std::remainder(a, 2 * kPi))) << a;
        }
}

}  // namespace
}  // namespace mobb
