// 200,000 random placements of real clips, per tree type, answered exactly as the brute force.
#include <gtest/gtest.h>

#include <random>

#include "data.h"
#include "mobb/core/brute.h"
#include "mobb/core/query.h"
#include "mobb/core/scan.h"
#include "mobb/core/sweep.h"

namespace mobb {
namespace {

constexpr TreeType kTypes[] = {TreeType::Mobb,    TreeType::Umobb, TreeType::Hybrid1,
                               TreeType::Hybrid2, TreeType::Mobb1, TreeType::Umobb1};

// Short walks and runs, long varied motions, dances with wide radii; some at 30 Hz so sample
// spacings differ within a query.
struct ClipSpec {
    const char* file;
    double fps;  // 0 = as recorded
};
constexpr ClipSpec kClips[] = {
    {"002_01.bvh", 0}, {"002_03.bvh", 0},  {"007_01.bvh", 0}, {"005_01.bvh", 30}, {"006_10.bvh", 0},
    {"005_02.bvh", 0}, {"005_17.bvh", 30}, {"002_05.bvh", 0}, {"001_01.bvh", 0},  {"001_14.bvh", 30},
};

struct Clips {
    std::vector<Path> paths;
    std::vector<std::vector<Tree>> trees;  // [type][clip]
    std::vector<ClipIndex> indexes;        // [clip], for collide_sweep and collide_scan
};

const Clips& clips() {
    static const Clips loaded = [] {
        Clips c;
        for (const ClipSpec& spec : kClips) {
            io::LoadOptions o;
            if (spec.fps > 0) o.fps = spec.fps;
            c.paths.push_back(io::load_clip(test::data_file(std::string("cmu/") + spec.file), o).path);
        }
        for (const Path& p : c.paths) c.indexes.push_back(ClipIndex::build(p));
        for (TreeType type : kTypes) {
            c.trees.emplace_back();
            for (const Path& p : c.paths) c.trees.back().push_back(Tree::build(p, {type, 10}));
        }
        return c;
    }();
    return loaded;
}

// Puts sample j of b near sample i of a, in space (0 to 3.2 m) and time (within 1.5 s), so
// both answers are common; then a random rotation of b about that sample.
void random_query(std::mt19937_64& rng, const Path& a, const Path& b, Placement& pa, Placement& pb) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const std::size_t i = std::size_t(u(rng) * double(a.size())) % a.size();
    const std::size_t j = std::size_t(u(rng) * double(b.size())) % b.size();
    pa = {20 * (u(rng) - 0.5), 20 * (u(rng) - 0.5), 6.283185307179586 * u(rng), 10 * (u(rng) - 0.5)};
    const Rigid2 ta = Rigid2::of(pa);
    const Sample& sa = a.samples[i];
    const double ax = ta.apply_x(sa.x, sa.y), ay = ta.apply_y(sa.x, sa.y);
    const double dist = 3.2 * u(rng), dir = 6.283185307179586 * u(rng);
    pb.theta = 6.283185307179586 * u(rng);
    const double c = std::cos(pb.theta), s = std::sin(pb.theta);
    const Sample& sb = b.samples[j];
    pb.x = ax + dist * std::cos(dir) - (c * sb.x - s * sb.y);
    pb.y = ay + dist * std::sin(dir) - (s * sb.x + c * sb.y);
    pb.t0 = pa.t0 + double(i) * a.dt - double(j) * b.dt + 3.0 * (u(rng) - 0.5);
}

TEST(RealClipsTest, EveryTreeTypeAgreesWithBruteForceOn200kPlacements) {
    MOBB_REQUIRE_MOCAP();
    const Clips& c = clips();
    std::mt19937_64 rng(2026);
    constexpr int kQueries = 200000;
    int positives = 0;
    std::vector<int> wrong(std::size(kTypes), 0);
    int wrong_sweep = 0, wrong_scan = 0;
    for (int q = 0; q < kQueries; ++q) {
        const std::size_t ia = rng() % c.paths.size(), ib = rng() % c.paths.size();
        Placement pa, pb;
        random_query(rng, c.paths[ia], c.paths[ib], pa, pb);
        const bool expected = collide_brute(c.paths[ia], pa, c.paths[ib], pb);
        positives += expected;
        for (std::size_t t = 0; t < std::size(kTypes); ++t) {
            const bool got = collide(c.trees[t][ia], pa, c.trees[t][ib], pb);
            if (got != expected && wrong[t]++ < 5)
                ADD_FAILURE() << to_string(kTypes[t]) << " query " << q << ": clips " << kClips[ia].file << " "
                              << kClips[ib].file << " expected " << expected;
        }
        if (collide_sweep(c.indexes[ia], pa, c.indexes[ib], pb) != expected && wrong_sweep++ < 5)
            ADD_FAILURE() << "circle sweep " << q << ": clips " << kClips[ia].file << " " << kClips[ib].file
                          << " expected " << expected;
        if (collide_scan(c.indexes[ia], pa, c.indexes[ib], pb) != expected && wrong_scan++ < 5)
            ADD_FAILURE() << "best scan " << q << ": clips " << kClips[ia].file << " " << kClips[ib].file
                          << " expected " << expected;
    }
    for (std::size_t t = 0; t < std::size(kTypes); ++t) EXPECT_EQ(wrong[t], 0) << to_string(kTypes[t]);
    EXPECT_EQ(wrong_sweep, 0) << "circle sweep";
    EXPECT_EQ(wrong_scan, 0) << "best scan";
    // A good share of both answers.
    EXPECT_GT(positives, kQueries / 5);
    EXPECT_LT(positives, kQueries * 4 / 5);
    std::printf("%d of %d placements collide\n", positives, kQueries);
}

// The circle sweep's plan boundaries on real clips: crowd-like grid-aligned start times (touching
// neighbour diagonals decided by one ulp) or shifted ones, overlaps of 0 to 160 samples at either end
// (around the scan / sweep switch), rotations at +-pi, huge global offsets.
TEST(RealClipsTest, FastQueryPlanBoundariesAgreeWithBruteForce) {
    MOBB_REQUIRE_MOCAP();
    const Clips& c = clips();
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int positives = 0;
    constexpr int kQueries = 60000;
    for (int q = 0; q < kQueries; ++q) {
        const std::size_t ia = rng() % c.paths.size(), ib = rng() % c.paths.size();
        const Path &a = c.paths[ia], &b = c.paths[ib];
        Placement pa, pb;
        random_query(rng, a, b, pa, pb);
        const double dt = a.dt;
        const auto overlap = double(int(u(rng) * 160));
        pa.t0 = double(int(u(rng) * 3000)) * dt;
        pb.t0 = q % 2 ? pa.t0 + (double(a.size()) - overlap) * dt : pa.t0 - (double(b.size()) - overlap) * b.dt;
        if (q % 3 == 1) pb.t0 += (u(rng) - 0.5) * dt;
        if (q % 5 == 0) pb.theta = q % 10 ? 3.141592653589793 : -3.141592653589793;
        if (q % 17 == 0) pa.x += 1e6, pb.x += 1e6, pa.t0 += 1e4, pb.t0 += 1e4;
        const bool expected = collide_brute(a, pa, b, pb);
        positives += expected;
        ASSERT_EQ(collide_sweep(c.indexes[ia], pa, c.indexes[ib], pb), expected) << q;
        ASSERT_EQ(collide_scan(c.indexes[ia], pa, c.indexes[ib], pb), expected) << q;
    }
    EXPECT_GT(positives, kQueries / 20);
    std::printf("%d of %d placements collide\n", positives, kQueries);
}

// Mixed tree types in one query (a viewer or crowd may hold trees of different kinds).
TEST(RealClipsTest, MixedTreeTypesAgreeWithBruteForce) {
    MOBB_REQUIRE_MOCAP();
    const Clips& c = clips();
    std::mt19937_64 rng(7);
    for (int q = 0; q < 20000; ++q) {
        const std::size_t ia = rng() % c.paths.size(), ib = rng() % c.paths.size();
        const std::size_t ta = rng() % std::size(kTypes), tb = rng() % std::size(kTypes);
        Placement pa, pb;
        random_query(rng, c.paths[ia], c.paths[ib], pa, pb);
        ASSERT_EQ(collide(c.trees[ta][ia], pa, c.trees[tb][ib], pb), collide_brute(c.paths[ia], pa, c.paths[ib], pb))
            << q;
    }
}

// The windowed brute force is itself checked against every pair on real clips.
TEST(RealClipsTest, BruteForceAgreesWithAllPairs) {
    MOBB_REQUIRE_MOCAP();
    const Clips& c = clips();
    std::mt19937_64 rng(8);
    for (int q = 0; q < 3000; ++q) {
        const std::size_t ia = rng() % 5, ib = rng() % 5;  // the short clips
        Placement pa, pb;
        random_query(rng, c.paths[ia], c.paths[ib], pa, pb);
        ASSERT_EQ(collide_brute(c.paths[ia], pa, c.paths[ib], pb), collide_all_pairs(c.paths[ia], pa, c.paths[ib], pb));
    }
}

}  // namespace
}  // namespace mobb
