// Per-sample path measures: ground speed by central differences.
#include <gtest/gtest.h>

#include <cmath>

#include "mobb/core/path.h"
#include "random_paths.h"

namespace mobb {
namespace {

TEST(SampleSpeeds, ConstantAlongALine) {
    Path p;
    p.dt = 0.02;
    for (int i = 0; i < 50; ++i) p.samples.push_back({0.03 * i, -0.04 * i, 0.3});  // 0.05 m per sample
    const std::vector<double> v = sample_speeds(p);
    ASSERT_EQ(v.size(), p.size());
    for (double x : v) EXPECT_NEAR(x, 2.5, 1e-9);
}

TEST(SampleSpeeds, CentralInsideOneSidedAtTheEnds) {
    Path p;
    p.dt = 0.5;
    p.samples = {{0, 0, 0.2}, {1, 0, 0.2}, {1, 3, 0.2}};
    const std::vector<double> v = sample_speeds(p);
    ASSERT_EQ(v.size(), 3u);
    EXPECT_NEAR(v[0], 2.0, 1e-12);                         // 1 m in 0.5 s
    EXPECT_NEAR(v[1], std::hypot(1.0, 3.0) / 1.0, 1e-12);  // (0,0) -> (1,3) over 2 dt
    EXPECT_NEAR(v[2], 6.0, 1e-12);                         // 3 m in 0.5 s
    EXPECT_EQ(sample_speeds(test::standing_still(1)), std::vector<double>{0.0});
    for (double x : sample_speeds(test::standing_still(20))) EXPECT_EQ(x, 0.0);
}

}  // namespace
}  // namespace mobb
