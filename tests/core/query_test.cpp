#include <gtest/gtest.h>

#include <random>

#include "mobb/core/brute.h"
#include "mobb/core/query.h"
#include "random_paths.h"

namespace mobb {
namespace {

constexpr TreeType kTypes[] = {TreeType::Mobb,    TreeType::Umobb, TreeType::Hybrid1,
                               TreeType::Hybrid2, TreeType::Mobb1, TreeType::Umobb1};

Placement random_placement(std::mt19937_64& rng, double spread, double t_spread) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    return {spread * (u(rng) - 0.5), spread * (u(rng) - 0.5), 6.283185307179586 * u(rng), t_spread * (u(rng) - 0.5)};
}

// Every tree type, n_min and axis fit answers exactly as the brute-force reference, which itself
// answers as the all-pairs definition.
TEST(QueryTest, AllTreeTypesAgreeWithBruteForceOnRandomWalks) {
    std::mt19937_64 rng(21);
    int positives = 0, total = 0;
    for (int clip = 0; clip < 12; ++clip) {
        const Path a = test::random_walk(rng, 20 + clip * 37);
        const Path b = test::random_walk(rng, 300 - clip * 20, clip % 3 ? 1.0 / 60 : 1.0 / 30);
        std::vector<Tree> ta, tb;
        for (TreeType type : kTypes)
            for (int n_min : {1, 10}) {
                ta.push_back(Tree::build(a, {type, n_min, clip % 2 ? AxisFit::Pca : AxisFit::Chord}));
                tb.push_back(Tree::build(b, {type, n_min}));
            }
        for (int q = 0; q < 400; ++q) {
            const Placement pa = random_placement(rng, 3, 3), pb = random_placement(rng, 3, 3);
            const bool expected = collide_brute(a, pa, b, pb);
            if (a.size() * b.size() < 40000) {
                ASSERT_EQ(expected, collide_all_pairs(a, pa, b, pb));
            }
            for (std::size_t i = 0; i < ta.size(); ++i)
                for (std::size_t j = 0; j < tb.size(); j += 3)
                    ASSERT_EQ(collide(ta[i], pa, tb[j], pb), expected) << clip << " " << q << " " << i << " " << j;
            positives += expected;
            ++total;
        }
    }
    EXPECT_GT(positives, total / 5);
    EXPECT_LT(positives, total * 4 / 5);
}

TEST(QueryTest, HitIsARealCollidingPair) {
    std::mt19937_64 rng(22);
    const Path a = test::random_walk(rng, 300), b = test::random_walk(rng, 300);
    const Tree ta = Tree::build(a), tb = Tree::build(b, {TreeType::Umobb});
    int hits = 0;
    for (int q = 0; q < 500; ++q) {
        const Placement pa = random_placement(rng, 6, 4), pb = random_placement(rng, 6, 4);
        SamplePair hit;
        if (!collide(ta, pa, tb, pb, nullptr, nullptr, &hit)) continue;
        ++hits;
        const auto i = hit.a, j = hit.b;
        EXPECT_TRUE(times_overlap(sample_time(pa, a.dt, i), sample_time(pa, a.dt, i + 1), sample_time(pb, b.dt, j),
                                  sample_time(pb, b.dt, j + 1)));
        EXPECT_TRUE(
            samples_overlap(Rigid2::of(pa), a.samples[std::size_t(i)], Rigid2::of(pb), b.samples[std::size_t(j)]));
    }
    EXPECT_GT(hits, 50);
}

// Touching is not colliding; any positive overlap in time and space is.
TEST(QueryTest, BoundariesAreStrict) {
    Path a = test::standing_still(10, 0.5), b = test::standing_still(10, 0.5);
    const Tree ta = Tree::build(a, {TreeType::Mobb, 2}), tb = Tree::build(b, {TreeType::Umobb, 2});
    const double d = 1.0 / 6;  // 10 samples at 60 Hz
    // Distance exactly r_a + r_b (1.0): no collision. Slightly less: collision.
    EXPECT_FALSE(collide(ta, {0, 0, 0, 0}, tb, {1.0, 0, 0, 0}));
    EXPECT_TRUE(collide(ta, {0, 0, 0, 0}, tb, {0.999999, 0, 0, 0}));
    // Back to back in time: no collision; overlapping by a sliver: collision.
    EXPECT_FALSE(collide(ta, {1, -2, 0, 0}, tb, {1, -2, 0, d}));
    EXPECT_TRUE(collide(ta, {1, -2, 0, 0}, tb, {1, -2, 0, d - 1e-9}));
    EXPECT_EQ(collide_brute(a, {1, -2, 0, 0}, b, {1, -2, 0, d}), false);
    EXPECT_EQ(collide_brute(a, {1, -2, 0, 0}, b, {1, -2, 0, d - 1e-9}), true);
}

TEST(QueryTest, DegeneratePathsAgreeWithBruteForce) {
    std::mt19937_64 rng(23);
    const std::vector<Path> paths = {test::standing_still(1), test::standing_still(50), test::circle(120),
                                     test::random_walk(rng, 2)};
    for (const Path& a : paths)
        for (const Path& b : paths)
            for (TreeType type : kTypes) {
                const Tree ta = Tree::build(a, {type, 4}), tb = Tree::build(b, {type, 4});
                for (int q = 0; q < 300; ++q) {
                    const Placement pa = random_placement(rng, 5, 3), pb = random_placement(rng, 5, 3);
                    ASSERT_EQ(collide(ta, pa, tb, pb), collide_all_pairs(a, pa, b, pb));
                }
            }
}

TEST(QueryTest, CountsAndTraceDescribeTheSameWork) {
    std::mt19937_64 rng(24);
    const Path a = test::random_walk(rng, 500), b = test::random_walk(rng, 500);
    for (TreeType type : kTypes) {
        const Tree ta = Tree::build(a, {type}), tb = Tree::build(b, {type});
        for (int q = 0; q < 100; ++q) {
            const Placement pa = random_placement(rng, 4, 2), pb = random_placement(rng, 4, 2);
            QueryStats counted, traced;
            Trace trace;
            SamplePair hit;
            const bool answer = collide(ta, pa, tb, pb, &counted);
            ASSERT_EQ(collide(ta, pa, tb, pb, &traced, &trace, &hit), answer);
            EXPECT_EQ(counted.tests2d, traced.tests2d);
            EXPECT_EQ(counted.tests3d, traced.tests3d);
            EXPECT_EQ(counted.samples, traced.samples);
            std::uint64_t box2 = 0, box3 = 0, samples = 0;
            for (const TraceEvent& e : trace) {
                box2 += e.test == TraceTest::Box2;
                box3 += e.test == TraceTest::Box3;
                samples += e.samples_tested;
                EXPECT_GE(e.node_a, 0);
                EXPECT_LT(std::size_t(e.node_a), ta.nodes().size());
                EXPECT_LT(std::size_t(e.node_b), tb.nodes().size());
            }
            EXPECT_EQ(box2, counted.tests2d);
            EXPECT_EQ(box3, counted.tests3d);
            EXPECT_EQ(samples, counted.samples);
            ASSERT_FALSE(trace.empty());
            EXPECT_EQ(trace.front().node_a, 0);
            EXPECT_EQ(trace.back().outcome == TraceOutcome::Hit, answer);
            if (answer) {
                EXPECT_EQ(trace.back().sample_a, hit.a);
                EXPECT_EQ(trace.back().sample_b, hit.b);
            }
        }
    }
}

/// tests_per_node() counts each tree's side of the trace: every non-descent event once on each side,
/// the roots tested first.
TEST(QueryTest, TestsPerNodeCountTheTrace) {
    std::mt19937_64 rng(26);
    const Path a = test::random_walk(rng, 500), b = test::random_walk(rng, 400);
    const Tree ta = Tree::build(a, {TreeType::Mobb}), tb = Tree::build(b, {TreeType::Umobb});
    int traces = 0;
    for (int q = 0; q < 50; ++q) {
        const Placement pa = random_placement(rng, 2, 1), pb = random_placement(rng, 2, 1);
        Trace trace;
        collide(ta, pa, tb, pb, nullptr, &trace);
        const std::vector<int> na = tests_per_node(trace, true, ta.nodes().size());
        const std::vector<int> nb = tests_per_node(trace, false, tb.nodes().size());
        ASSERT_EQ(na.size(), ta.nodes().size());
        ASSERT_EQ(nb.size(), tb.nodes().size());
        long tested = 0;
        for (const TraceEvent& e : trace) tested += e.test != TraceTest::Descend;
        long sa = 0, sb = 0;
        for (int x : na) sa += x;
        for (int x : nb) sb += x;
        EXPECT_EQ(sa, tested);
        EXPECT_EQ(sb, tested);
        EXPECT_GE(na[0], 1);
        traces += trace.size() > 3;
    }
    EXPECT_GT(traces, 10);
}

TEST(QueryTest, TypesCountTheirOwnBoxTests) {
    std::mt19937_64 rng(25);
    const Path a = test::random_walk(rng, 600), b = test::random_walk(rng, 600);
    QueryStats mobb, umobb;
    for (int q = 0; q < 200; ++q) {
        const Placement pa = random_placement(rng, 4, 2), pb = random_placement(rng, 4, 2);
        collide(Tree::build(a, {TreeType::Mobb}), pa, Tree::build(b, {TreeType::Mobb}), pb, &mobb);
        collide(Tree::build(a, {TreeType::Umobb}), pa, Tree::build(b, {TreeType::Umobb}), pb, &umobb);
    }
    EXPECT_GT(mobb.tests2d, 0u);
    EXPECT_EQ(mobb.tests3d, 0u);
    EXPECT_GT(umobb.tests3d, umobb.tests2d);
}

TEST(QueryTest, LeafTestSkipsToTheOverlappingTime) {
    // A 1-level query on two long clips far apart in time overlap only at the end: the binary search
    // means only the overlapping samples are tested.
    const Path a = test::standing_still(1000), b = test::standing_still(1000);
    QueryStats stats;
    const Tree ta = Tree::build(a, {TreeType::Mobb1}), tb = Tree::build(b, {TreeType::Mobb1});
    const double dt = a.dt;
    EXPECT_TRUE(collide(ta, {0, 0, 0, 0}, tb, {0, 0, 0, 995.5 * dt}, &stats));
    EXPECT_EQ(stats.samples, 1u);
    stats = {};
    EXPECT_FALSE(collide(ta, {0, 0, 0, 0}, tb, {0.45, 0.45, 0, 995.5 * dt}, &stats));  // 0.636 m > 0.6 m
    EXPECT_EQ(stats.samples, 9u);  // samples 995..999 of a against 0..4 of b, two each but the last
}

}  // namespace
}  // namespace mobb
