// The flow through a line (flow.h) on windows made by hand: crossing times worked out from the samples,
// each agent counted once, and the rate and headway from their definitions.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>

#include "mobb/crowd/metrics/flow.h"

namespace mobb::crowd {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Frames first .. last - 1 of `agents` agents at 2 Hz, agent a at frame f at x = x(a, f), y = 0.
SampleWindow window(std::int64_t first, std::int64_t last, std::size_t agents,
                    const std::function<double(std::size_t, std::int64_t)>& x) {
    SampleWindow w;
    w.dt = 0.5, w.frames = 20, w.agents = agents, w.first = first, w.last = last, w.agent_last = agents;
    for (std::int64_t f = first; f < last; ++f)
        for (std::size_t a = 0; a < agents; ++a) w.samples.push_back({double(f) * w.dt, x(a, f), 0.0, 0.3});
    return w;
}

TEST(Flow, LinesParse) {
    EXPECT_EQ(parse_flow_line("x=5").axis, 0);
    EXPECT_DOUBLE_EQ(parse_flow_line("x=5").at, 5.0);
    const FlowLine y = parse_flow_line(" y = -2.5 ");
    EXPECT_EQ(y.axis, 1);
    EXPECT_DOUBLE_EQ(y.at, -2.5);
    for (const char* bad : {"z=1", "x5", "x=", "x=1m", "x=nan", "", "=3"})
        EXPECT_THROW(parse_flow_line(bad), std::invalid_argument) << bad;
}

// Agent 0 walks +x through x = 4.5 (between frames 4 and 5: at 4.5 frames, 2.25 s), then back again
// (not counted); agent 1 walks -x from 10 through it (x = 10 - 2f: 4.5 at 2.75 frames, 1.375 s); agent 2
// stands; agent 3 leaves the run (NaN) before it would cross. Read in two windows split at the crossing
// of agent 0, and whole: the same crossings.
TEST(Flow, EachAgentsFirstCrossingBetweenFrames) {
    const auto x = [](std::size_t a, std::int64_t f) -> double {
        if (a == 0) return f <= 10 ? double(f) : double(20 - f);
        if (a == 1) return 10.0 - 2.0 * double(f);
        if (a == 2) return 1.0;
        return f < 3 ? 1.0 + double(f) : kNaN;  // 1, 2, 3, then gone
    };
    FlowCounter split({0, 4.5}, 4);
    split.add(window(0, 5, 4, x));
    split.add(window(5, 20, 4, x));
    FlowCounter whole({0, 4.5}, 4);
    whole.add(window(0, 20, 4, x));
    for (const FlowCounter* counter : {&split, &whole}) {
        const std::vector<Crossing> c = counter->crossings();
        ASSERT_EQ(c.size(), 2u);
        EXPECT_EQ(c[0].agent, 1u);
        EXPECT_DOUBLE_EQ(c[0].time, 1.375);
        EXPECT_EQ(c[0].way, -1);
        EXPECT_EQ(c[1].agent, 0u);
        EXPECT_DOUBLE_EQ(c[1].time, 2.25);
        EXPECT_EQ(c[1].way, 1);
    }
}

TEST(Flow, RateBetweenThe10thAnd90thPercentileAndMedianHeadway) {
    // Eleven crossings: 0, 1, ..., 7 s one a second, then 10, 20, 30 s (a queue, then stragglers).
    std::vector<Crossing> c;
    c.reserve(11);
    for (int i = 0; i < 8; ++i) c.push_back({std::size_t(i), double(i), i % 2 ? 1 : -1});
    for (int i = 0; i < 3; ++i) c.push_back({std::size_t(8 + i), 10.0 * (i + 1), -1});
    const Flow f = flow_of(c);
    EXPECT_EQ(f.crossings, 11u);
    EXPECT_EQ(f.forward, 4u);
    EXPECT_EQ(f.backward, 7u);
    EXPECT_DOUBLE_EQ(f.first, 0.0);
    EXPECT_DOUBLE_EQ(f.last, 30.0);
    // Indices round(0.1 x 10) = 1 and round(0.9 x 10) = 9: 8 crossings from 1 s to 20 s.
    EXPECT_DOUBLE_EQ(f.rate_from, 1.0);
    EXPECT_DOUBLE_EQ(f.rate_to, 20.0);
    EXPECT_DOUBLE_EQ(f.rate, 8.0 / 19.0);
    EXPECT_DOUBLE_EQ(f.median_headway, 1.0);  // gaps 1 (x7), 3, 10, 10
    // Two crossings: a headway, no rate; none: nothing.
    const Flow two = flow_of({{0, 1.0, 1}, {1, 4.0, 1}});
    EXPECT_DOUBLE_EQ(two.median_headway, 3.0);
    EXPECT_DOUBLE_EQ(two.rate, 0.0);
    EXPECT_EQ(flow_of({}).crossings, 0u);
}

}  // namespace
}  // namespace mobb::crowd
