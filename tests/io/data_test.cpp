// The real motion capture (../shared/mocap or $MOBB_DATA): counts, rates, lengths, units, GLB = BVH,
// options and warnings. Skipped without the data, failed without it when MOBB_REQUIRE_DATA=1.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "mobb/io/load.h"
#include "test_util.h"

namespace mobb::io {
namespace {

// The table of the data's README (independent numpy reader): frames, duration (s), root ground-path length (m),
// and whether frame 0 is a stray T-pose. The lengths of 007_03..007_12 include the stray frame's 2.1-2.7 m jump
// (with it our lengths match to 0.05 m; without it they are 2.2-2.7 m short).
struct Row {
    const char* name;
    int frames;
    double duration;
    double length;
    bool stray;
};

const Row kTable[] = {
    {"001_01", 1376, 22.93, 14.0, false}, {"001_08", 1305, 21.75, 10.0, false}, {"001_14", 1169, 19.48, 16.4, false},
    {"002_01", 171, 2.85, 3.8, false},    {"002_02", 148, 2.47, 4.6, false},    {"002_03", 86, 1.43, 4.2, false},
    {"002_04", 241, 4.02, 1.0, false},    {"002_05", 927, 15.45, 2.0, false},   {"002_06", 1118, 18.63, 4.2, false},
    {"002_07", 1126, 18.77, 2.8, false},  {"002_08", 750, 12.50, 3.3, false},   {"002_09", 517, 8.62, 2.0, false},
    {"002_10", 1323, 22.05, 3.1, false},  {"005_01", 299, 4.98, 5.2, false},    {"005_02", 562, 9.37, 2.5, false},
    {"005_03", 216, 3.60, 1.8, false},    {"005_04", 600, 10.00, 2.9, false},   {"005_05", 458, 7.63, 4.1, false},
    {"005_06", 443, 7.38, 4.4, false},    {"005_07", 596, 9.93, 5.1, false},    {"005_08", 361, 6.02, 4.7, false},
    {"005_09", 572, 9.53, 2.2, false},    {"005_10", 409, 6.82, 1.9, false},    {"005_11", 296, 4.93, 2.4, false},
    {"005_12", 677, 11.28, 1.8, false},   {"005_13", 548, 9.13, 3.3, false},    {"005_14", 321, 5.35, 5.0, false},
    {"005_15", 270, 4.50, 4.1, false},    {"005_16", 263, 4.38, 4.9, false},    {"005_17", 522, 8.70, 5.1, false},
    {"005_18", 915, 15.25, 4.8, false},   {"005_19", 430, 7.17, 4.2, false},    {"005_20", 548, 9.13, 4.5, false},
    {"006_01", 246, 4.10, 4.8, false},    {"006_02", 361, 6.02, 5.5, false},    {"006_03", 264, 4.40, 4.7, false},
    {"006_04", 197, 3.28, 4.9, false},    {"006_05", 192, 3.20, 4.3, false},    {"006_06", 200, 3.33, 4.4, false},
    {"006_07", 288, 4.80, 5.2, false},    {"006_08", 170, 2.83, 3.7, false},    {"006_09", 150, 2.50, 3.9, false},
    {"006_10", 557, 9.28, 4.9, false},    {"006_11", 573, 9.55, 5.6, false},    {"006_12", 611, 10.18, 5.5, false},
    {"007_01", 157, 2.62, 4.1, false},    {"007_02", 164, 2.73, 4.2, false},    {"007_03", 208, 3.47, 6.3, true},
    {"007_04", 225, 3.75, 6.2, true},     {"007_05", 259, 4.32, 7.3, true},     {"007_06", 209, 3.48, 7.7, true},
    {"007_07", 190, 3.17, 7.6, true},     {"007_08", 181, 3.02, 7.1, true},     {"007_09", 153, 2.55, 6.8, true},
    {"007_10", 151, 2.52, 7.0, true},     {"007_11", 158, 2.63, 7.8, true},     {"007_12", 132, 2.20, 7.4, true},
};

void PrintTo(const Row& row, std::ostream* out) { *out << row.name; }

const char* const kGlbs[] = {"002_01", "002_03", "005_01", "001_01", "007_02", "006_02"};

double length(const Path& p, std::size_t from = 1) {
    double sum = 0;
    for (std::size_t i = std::max<std::size_t>(from, 1); i < p.size(); ++i)
        sum += std::hypot(p.samples[i].x - p.samples[i - 1].x, p.samples[i].y - p.samples[i - 1].y);
    return sum;
}

double median_r(const Path& p) {
    std::vector<double> r;
    for (const Sample& s : p.samples) r.push_back(s.r);
    std::nth_element(r.begin(), r.begin() + std::ptrdiff_t(r.size() / 2), r.end());
    return r[r.size() / 2];
}

class CmuTable : public ::testing::TestWithParam<Row> {};
class RealData : public test::DataTest {};

TEST_P(CmuTable, MatchesTheReadme) {
    MOBB_NEED_DATA(dir);
    const Row& row = GetParam();
    const Clip clip = load_clip(dir + "/cmu/" + row.name + ".bvh");
    EXPECT_EQ(clip.source_frames, row.frames);
    EXPECT_EQ(int(clip.path.size()), row.frames);
    EXPECT_EQ(clip.path.dt, 1.0 / 60.0);  // Frame Time 0.016667 read as 60 fps
    EXPECT_NEAR(clip.path.duration(), row.duration, 0.005 + 1e-9);
    EXPECT_NEAR(length(clip.path), row.length, std::max(0.05 * row.length, 0.2));
    EXPECT_EQ(clip.scale, 0.01);
    EXPECT_EQ(clip.scale_reason.rfind("auto: centimetres (standing height ", 0), 0u) << clip.scale_reason;
    EXPECT_EQ(clip.warnings.size(), row.stray ? 1u : 0u);
    if (row.stray) {
        EXPECT_NE(clip.warnings[0].find(": frame 1: root jumps "), std::string::npos) << clip.warnings[0];
        EXPECT_LT(length(clip.path, 2), row.length - 2.0);  // the table counts the stray jump
    }
}

INSTANTIATE_TEST_SUITE_P(Readme, CmuTable, ::testing::ValuesIn(kTable),
                         [](const ::testing::TestParamInfo<Row>& row) { return std::string("cmu_") + row.param.name; });

TEST_F(RealData, WalksHavePlausibleSpeedAndRadiusInMetres) {
    for (const char* name : {"002_01", "007_01", "005_01", "006_01"}) {
        const Clip clip = load_clip(cmu(name));
        const double speed = length(clip.path) / clip.path.duration();
        const double r = median_r(clip.path);
        std::cout << name << ": " << clip.scale_reason << ", speed " << speed << " m/s, median r " << r << " m\n";
        RecordProperty(std::string(name) + "_scale", clip.scale_reason);
        EXPECT_GE(speed, 0.8) << name;
        EXPECT_LE(speed, 2.0) << name;
        EXPECT_GE(r, 0.15) << name;
        EXPECT_LE(r, 0.6) << name;
        EXPECT_EQ(clip.scale, 0.01) << name;
    }
}

TEST_F(RealData, GlbPathsEqualBvhPathsSampleBySample) {
    // Blender re-exported these BVH files; joints are the same (the BVH End Sites all have zero offsets, so
    // they add nothing to r), keys at 60 Hz, one key per BVH frame.
    for (const char* name : kGlbs) {
        const Clip g = load_clip(glb(name));
        const Clip b = load_clip(cmu(name));
        ASSERT_EQ(g.path.size(), b.path.size()) << name;
        EXPECT_EQ(g.path.dt, b.path.dt) << name;
        EXPECT_EQ(g.animation.skeleton.size() + 41, b.animation.skeleton.size()) << name << ": BVH has 41 End Sites";
        double worst_p = 0, worst_r = 0;
        for (std::size_t i = 0; i < g.path.size(); ++i) {
            const Sample& x = g.path.samples[i];
            const Sample& y = b.path.samples[i];
            worst_p = std::max(worst_p, std::hypot(x.x - y.x, x.y - y.y));
            worst_r = std::max(worst_r, std::abs(x.r - y.r));
        }
        EXPECT_LT(worst_p, 1e-3) << name;
        EXPECT_LT(worst_r, 1e-3) << name;
        EXPECT_TRUE(g.warnings.empty()) << name;
    }
}

TEST_F(RealData, FramesFpsUpAndScaleOnRealData) {
    const std::string file = cmu("002_01");
    const Clip full = load_clip(file);
    LoadOptions o;
    o.frame_begin = 10;
    o.frame_end = 20;
    const Clip part = load_clip(file, o);
    ASSERT_EQ(part.path.size(), 10u);
    for (std::size_t i = 0; i < 10; ++i) {
        EXPECT_EQ(part.path.samples[i].x, full.path.samples[10 + i].x);
        EXPECT_EQ(part.path.samples[i].y, full.path.samples[10 + i].y);
        EXPECT_EQ(part.path.samples[i].r, full.path.samples[10 + i].r);
    }

    o = {};
    o.fps = 30;
    const Clip half = load_clip(file, o);
    ASSERT_EQ(half.path.size(), 86u);  // 171 frames: 0, 2, ..., 170
    EXPECT_EQ(half.path.dt, 1.0 / 30.0);
    for (std::size_t k = 0; k < half.path.size(); ++k) EXPECT_EQ(half.path.samples[k].x, full.path.samples[2 * k].x);

    o = {};
    o.up = UpAxis::Z;
    const Clip z = load_clip(file, o);
    for (int f = 0; f < full.animation.frames(); f += 17) {
        const glm::dvec3 root = full.animation.at(f, full.animation.skeleton.root);
        EXPECT_EQ(z.path.samples[std::size_t(f)].x, root.x);
        EXPECT_EQ(z.path.samples[std::size_t(f)].y, root.y);      // Z-up: ground (X, Y)
        EXPECT_EQ(full.path.samples[std::size_t(f)].y, -root.z);  // Y-up: ground (X, -Z)
    }

    o = {};
    o.scale = 0.01;
    const Clip cm = load_clip(file, o);
    o.scale = 0.02;
    const Clip doubled = load_clip(file, o);
    for (std::size_t i = 0; i < cm.path.size(); i += 10) {
        EXPECT_DOUBLE_EQ(doubled.path.samples[i].x, 2 * cm.path.samples[i].x);
        EXPECT_DOUBLE_EQ(doubled.path.samples[i].r, 2 * cm.path.samples[i].r);
        EXPECT_DOUBLE_EQ(cm.path.samples[i].x, full.path.samples[i].x);
    }

    o = {};
    o.frame_begin = 10;
    o.frame_end = 20;
    const Clip glb_part = load_clip(glb("002_01"), o);
    ASSERT_EQ(glb_part.path.size(), 10u);
    EXPECT_NEAR(glb_part.path.samples[0].x, full.path.samples[10].x, 1e-3);
}

TEST_F(RealData, StrayFrameWarningAndTrimming) {
    const Clip stray = load_clip(cmu("007_03"));
    ASSERT_EQ(stray.warnings.size(), 1u);
    std::cout << stray.warnings[0] << "\n";
    EXPECT_EQ(stray.warnings[0].rfind(cmu("007_03") + ": frame 1: root jumps 2.", 0), 0u) << stray.warnings[0];
    EXPECT_TRUE(load_clip(cmu("002_01")).warnings.empty());
    LoadOptions o;
    o.frame_begin = 1;
    o.frame_end = stray.source_frames;
    const Clip trimmed = load_clip(cmu("007_03"), o);
    EXPECT_TRUE(trimmed.warnings.empty());
    EXPECT_EQ(int(trimmed.path.size()), stray.source_frames - 1);
}

TEST_F(RealData, DamagedCopiesOfRealFilesAreErrors) {
    const test::TempDir tmp;
    const auto read = [](const std::string& file) {
        std::ifstream in(file, std::ios::binary);
        std::stringstream ss;
        ss << in.rdbuf();
        return ss.str();
    };
    const std::string bvh = read(cmu("002_01"));
    const std::string cut = tmp.write("cut.bvh", bvh.substr(0, bvh.size() / 2));
    const std::string message = test::load_error([&] { load_clip(cut); });
    const auto lines = std::count(bvh.begin(), bvh.begin() + std::ptrdiff_t(bvh.size() / 2), '\n');
    EXPECT_EQ(message.rfind(cut + ":" + std::to_string(lines + 1) + ": frame ", 0), 0u) << message;

    const std::string glb_bytes = read(glb("002_03"));
    const std::string half = tmp.write("half.glb", glb_bytes.substr(0, glb_bytes.size() / 2));
    EXPECT_EQ(test::load_error([&] { load_clip(half); }).rfind(half + ": GLB: not a valid file", 0), 0u);
    std::string flipped = glb_bytes;
    for (std::size_t i = 100; i < flipped.size(); i += 997) flipped[i] = char(flipped[i] ^ 0x5a);
    const std::string noisy = tmp.write("noisy.glb", flipped);
    EXPECT_EQ(test::load_error([&] { load_clip(noisy); }).rfind(noisy + ": ", 0), 0u);
}

}  // namespace
}  // namespace mobb::io
