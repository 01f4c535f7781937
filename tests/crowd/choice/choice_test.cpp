// The choice point's placement of candidate clips: a placed clip's box, found by walking the hull from
// its extreme vertices, is exactly the box of every hull vertex placed (the decisions depend on it).
#include <cmath>
#include <random>
#include <stdexcept>
#include <utility>

#include <gtest/gtest.h>

#include "choice/choice.h"
#include "mobb/crowd/graph/motion_graph.h"

namespace mobb::crowd {
namespace {

const std::string kGraph = std::string(MOBB_SOURCE_DIR) + "/assets/graphs/cmu_locomotion.json";

// Every hull vertex placed, as Rigid2 rounds it, then padded by r_max.
SpaceTimeBox brute_box(const ClipOutline& o, const Rigid2& m) {
    SpaceTimeBox b{1e300, 1e300, -1e300, -1e300, 0, 0};
    for (const auto& v : o.hull) {
        const double x = m.apply_x(v[0], v[1]), y = m.apply_y(v[0], v[1]);
        b.x0 = std::min(b.x0, x), b.y0 = std::min(b.y0, y), b.x1 = std::max(b.x1, x), b.y1 = std::max(b.y1, y);
    }
    b.x0 -= o.r_max, b.y0 -= o.r_max, b.x1 += o.r_max, b.y1 += o.r_max;
    return b;
}

void expect_same_box(const ClipOutline& o, const Placement& p, int& wrong) {
    const Rigid2 m = Rigid2::of(p);
    const SpaceTimeBox got = place_clip(o, 0, 10, p, m, 0, nullptr).box, want = brute_box(o, m);
    // Bit for bit: a box one ulp off could change which pieces a query meets.
    wrong += got.x0 != want.x0 || got.y0 != want.y0 || got.x1 != want.x1 || got.y1 != want.y1;
}

Placement random_placement(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> pos(-500, 500), turn(-40, 40);
    Placement p{pos(rng), pos(rng), turn(rng), 0};
    if (rng() % 8 == 0) p.theta = double(rng() % 64) * (2 * M_PI / 64);  // on a bin's edge
    if (rng() % 8 == 0) p.theta = double(rng() % 8) * (M_PI / 4);        // axis-aligned and diagonal
    return p;
}

TEST(PlaceClip, BoxIsTheBoxOfEveryHullVertexForTheGraphsClips) {
    const MotionGraph g = load_graph(kGraph);
    const std::vector<ClipOutline> outlines = outlines_of(g);
    std::mt19937_64 rng(7);
    int wrong = 0;
    for (const ClipOutline& o : outlines)
        for (int k = 0; k < 2000; ++k) expect_same_box(o, random_placement(rng), wrong);
    EXPECT_EQ(wrong, 0);
}

// A route's held ground placed from the table (EscapeTable::ends) is where chaining the route's clips from
// the candidate's placement puts it, as the crowd's plans do.
TEST(EscapeTable, RouteEndsAreWhereTheRoutesHoldGround) {
    const MotionGraph g = load_graph(kGraph);
    const EscapeTable t = EscapeTable::build(g);
    std::mt19937_64 rng(5);
    int routes = 0;
    double worst = 0;
    for (int c = 0; c < int(g.clips.size()); ++c) {
        ASSERT_EQ(t.ends[std::size_t(c)].size(), t.routes[std::size_t(c)].size());
        for (std::size_t r = 0; r < t.routes[std::size_t(c)].size(); ++r) {
            const Placement start = random_placement(rng);
            Placement p = start;
            int prev = c;
            for (int next : t.routes[std::size_t(c)][r]) p = g.next(p, std::exchange(prev, next));
            const Rigid2 m = Rigid2::of(start);
            const auto& [x, y] = t.ends[std::size_t(c)][r];
            worst = std::max(worst, std::hypot(m.apply_x(x, y) - p.x, m.apply_y(x, y) - p.y));
            ++routes;
        }
    }
    EXPECT_GT(routes, 500);
    EXPECT_LT(worst, 1e-9);
    CrowdTuning too_many;
    too_many.escape.routes = EscapeTable::kMaxRoutes + 1;
    EXPECT_THROW(EscapeTable::build(g, too_many), std::invalid_argument);
}

// Hulls with near-ties: many points on a circle (nearly collinear neighbours), a thin sliver, tiny and
// huge ones.
TEST(PlaceClip, BoxIsTheBoxOfEveryHullVertexForHardHulls) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> unit(0, 1);
    int wrong = 0;
    for (int shape = 0; shape < 200; ++shape) {
        Path path;
        const int n = 3 + int(rng() % 400);
        const double scale = std::pow(10.0, double(int(rng() % 9)) - 4), squash = shape % 3 == 0 ? 1e-6 : 1;
        for (int i = 0; i < n; ++i) {
            const double a = 2 * M_PI * (shape % 2 ? unit(rng) : double(i) / n);
            path.samples.push_back({scale * std::cos(a), scale * squash * std::sin(a), 0.25});
        }
        const ClipOutline o = outline_of(path);
        for (int k = 0; k < 200; ++k) expect_same_box(o, random_placement(rng), wrong);
    }
    EXPECT_EQ(wrong, 0);
}

}  // namespace
}  // namespace mobb::crowd
