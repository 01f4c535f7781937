// load_clip on small generated BVH files: units, --frames, --fps, --up, --scale, warnings, file errors.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <sys/stat.h>

#include "mobb/io/load.h"
#include "test_util.h"

namespace mobb::io {
namespace {

// A root walking along +X by `step` per frame (file units) at 60 Hz, with a head End Site `height`
// above it and a hand End Site `reach` to the side (file Z). `jump_at` > 0 adds `jump` to X from that
// frame on.
std::string walk_bvh(int frames, double step, double height, double reach, int jump_at = -1, double jump = 0) {
    std::string text =
        "HIERARCHY\nROOT hips\n{\n\tOFFSET 0 0 0\n"
        "\tCHANNELS 6 Xposition Yposition Zposition Zrotation Yrotation Xrotation\n"
        "\tEnd Site\n\t{\n\t\tOFFSET 0 " +
        std::to_string(height) +
        " 0\n\t}\n"
        "\tJOINT hand\n\t{\n\t\tOFFSET 0 0 " +
        std::to_string(reach) +
        "\n\t\tCHANNELS 3 Zrotation Xrotation Yrotation\n"
        "\t\tEnd Site\n\t\t{\n\t\t\tOFFSET 0 0 0\n\t\t}\n\t}\n}\n"
        "MOTION\nFrames: " +
        std::to_string(frames) + "\nFrame Time: 0.016667\n";
    for (int f = 0; f < frames; ++f) {
        const double x = step * f + (jump_at >= 0 && f >= jump_at ? jump : 0.0);
        text += std::to_string(x) + " 0 0 0 0 0 0 0 0\n";
    }
    return text;
}

class Load : public ::testing::Test {
protected:
    std::string write(const std::string& name, const std::string& text) { return dir_.write(name, text); }
    test::TempDir dir_;
};

TEST_F(Load, AutoScaleChoosesTheUnitClosestToAPerson) {
    struct Case {
        double height;
        double scale;
        const char* unit;
    };
    for (const Case c : {Case{1.7, 1.0, "metres"}, Case{172.3, 0.01, "centimetres"}, Case{67, 0.0254, "inches"},
                         Case{30, 0.056444, "CMU units"}}) {
        const Clip clip = load_clip(write("h.bvh", walk_bvh(5, 0, c.height, 0)));
        EXPECT_DOUBLE_EQ(clip.scale, c.scale) << c.height;
        EXPECT_EQ(clip.scale_reason.rfind(std::string("auto: ") + c.unit + " (standing height ", 0), 0u)
            << clip.scale_reason;
        EXPECT_NEAR(clip.animation.at(0, 1).y, c.height * c.scale, 1e-9);
    }
    EXPECT_EQ(load_clip(write("h.bvh", walk_bvh(5, 0, 172.3, 0))).scale_reason,
              "auto: centimetres (standing height 172.3 units)");
}

TEST(GuessScale, BoundariesAreGeometricMeans) {
    EXPECT_EQ(guess_scale(7.0).scale, 1.0);
    EXPECT_EQ(guess_scale(7.3).scale, 0.056444);
    EXPECT_EQ(guess_scale(44).scale, 0.056444);
    EXPECT_EQ(guess_scale(46).scale, 0.0254);
    EXPECT_EQ(guess_scale(106).scale, 0.0254);
    EXPECT_EQ(guess_scale(108).scale, 0.01);
    EXPECT_EQ(guess_scale(1e6).scale, 0.01);
    EXPECT_EQ(guess_scale(0).scale, 1.0);
    EXPECT_EQ(guess_scale(std::nan("")).scale, 1.0);
}

TEST_F(Load, ExplicitScaleMultipliesEverything) {
    const std::string file = write("w.bvh", walk_bvh(20, 3, 170, 40));
    LoadOptions o;
    o.scale = 0.01;
    const Clip a = load_clip(file, o);
    o.scale = 0.02;
    const Clip b = load_clip(file, o);
    EXPECT_EQ(b.scale_reason, "given: 0.02 m per unit");
    ASSERT_EQ(a.path.size(), b.path.size());
    for (std::size_t i = 0; i < a.path.size(); ++i) {
        EXPECT_DOUBLE_EQ(b.path.samples[i].x, 2 * a.path.samples[i].x);
        EXPECT_DOUBLE_EQ(b.path.samples[i].y, 2 * a.path.samples[i].y);
        EXPECT_DOUBLE_EQ(b.path.samples[i].r, 2 * a.path.samples[i].r);
    }
    EXPECT_DOUBLE_EQ(a.path.samples[0].r, 0.4);
    for (const double bad : {0.0, -1.0, std::nan(""), HUGE_VAL}) {
        o.scale = bad;
        EXPECT_NE(test::load_error([&] { load_clip(file, o); }).find(file + ": --scale"), std::string::npos);
    }
}

TEST_F(Load, UpAxisChoosesTheGroundPlane) {
    const std::string file = write("w.bvh", walk_bvh(3, 0, 170, 40));
    LoadOptions o;
    o.scale = 1.0;
    const Clip y = load_clip(file, o);  // ground (X, -Z): the hand (Z = 40) is at ground y = -40
    EXPECT_EQ(y.up, UpAxis::Y);
    EXPECT_DOUBLE_EQ(y.path.samples[0].r, 40);
    o.up = UpAxis::Z;
    const Clip z = load_clip(file, o);  // ground (X, Y): the head (Y = 170) is 170 away
    EXPECT_EQ(z.up, UpAxis::Z);
    EXPECT_DOUBLE_EQ(z.path.samples[0].r, 170);
}

TEST_F(Load, FramesKeepsARange) {
    const std::string file = write("w.bvh", walk_bvh(30, 1, 170, 40));
    const Clip full = load_clip(file);
    EXPECT_EQ(full.source_frames, 30);
    EXPECT_DOUBLE_EQ(full.source_dt, 0.016667);
    EXPECT_DOUBLE_EQ(full.path.dt, 1.0 / 60.0);
    LoadOptions o;
    o.frame_begin = 10;
    o.frame_end = 20;
    const Clip part = load_clip(file, o);
    ASSERT_EQ(part.path.size(), 10u);
    EXPECT_EQ(part.animation.frames(), 10);
    EXPECT_EQ(part.source_frames, 30);
    for (int i = 0; i < 10; ++i) {
        EXPECT_EQ(part.source_index[std::size_t(i)], 10 + i);
        EXPECT_EQ(part.path.samples[std::size_t(i)].x, full.path.samples[std::size_t(10 + i)].x);
        EXPECT_EQ(part.animation.at(i, 1), full.animation.at(10 + i, 1));
    }
    o.frame_begin = 25;
    o.frame_end = -1;
    EXPECT_EQ(load_clip(file, o).path.size(), 5u);
    for (const auto& [a, b] : {std::pair{5, 5}, {-1, 3}, {0, 31}, {30, -1}, {7, 3}, {0, -2}}) {
        o.frame_begin = a;
        o.frame_end = b;
        const std::string message = test::load_error([&] { load_clip(file, o); });
        EXPECT_EQ(message.rfind(file + ": --frames", 0), 0u) << a << ":" << b << " " << message;
    }
}

TEST_F(Load, FpsTakesTheFrameAtOrJustBelowEachNewSampleTime) {
    const std::string file = write("w.bvh", walk_bvh(31, 1, 170, 40));
    const Clip full = load_clip(file);
    LoadOptions o;
    o.fps = 30;
    const Clip half = load_clip(file, o);
    EXPECT_DOUBLE_EQ(half.path.dt, 1.0 / 30.0);
    ASSERT_EQ(half.path.size(), 16u);  // samples at k/30 < 31/60
    for (std::size_t k = 0; k < half.path.size(); ++k) {
        EXPECT_EQ(half.source_index[k], int(2 * k));
        EXPECT_EQ(half.path.samples[k].x, full.path.samples[2 * k].x);
    }
    o.fps = 24;  // k * 2.5 frames: 0, 2, 5, 7, 10, ...
    const Clip film = load_clip(file, o);
    EXPECT_EQ(film.path.size(), 13u);
    EXPECT_EQ(std::vector<int>(film.source_index.begin(), film.source_index.begin() + 5),
              (std::vector<int>{0, 2, 5, 7, 10}));
    o.fps = 60;
    EXPECT_EQ(load_clip(file, o).source_index, full.source_index);
    o.fps = 120;  // upsampling repeats frames
    EXPECT_EQ(std::vector<int>(load_clip(file, o).source_index).size(), 62u);
    // Frames first, then fps.
    o.fps = 30;
    o.frame_begin = 1;
    o.frame_end = 21;
    const Clip both = load_clip(file, o);
    ASSERT_EQ(both.path.size(), 10u);
    EXPECT_EQ(both.source_index[1], 3);
    for (const double bad : {0.0, -30.0, std::nan(""), 1e300}) {
        o.fps = bad;
        EXPECT_EQ(test::load_error([&] { load_clip(file, o); }).rfind(file + ": --fps", 0), 0u) << bad;
    }
}

TEST_F(Load, RootJumpsAreWarnedAndTrimmable) {
    // 1 cm per frame at 0.01 m per unit, with a 100-unit (1 m) jump into frame 4.
    const std::string file = write("jump.bvh", walk_bvh(20, 1, 170, 40, 4, 100));
    const Clip clip = load_clip(file);
    ASSERT_EQ(clip.warnings.size(), 1u);
    EXPECT_EQ(clip.warnings[0].rfind(file + ": frame 4: root jumps 1.01 m", 0), 0u) << clip.warnings[0];
    LoadOptions o;
    o.frame_begin = 4;
    EXPECT_TRUE(load_clip(file, o).warnings.empty());
    // 0.4 m is not a jump.
    EXPECT_TRUE(load_clip(write("small.bvh", walk_bvh(20, 1, 170, 40, 4, 40))).warnings.empty());
}

TEST_F(Load, FileErrorsNameTheFile) {
    const std::string missing = (dir_.path() / "missing.bvh").string();
    EXPECT_EQ(test::load_error([&] { load_clip(missing); }).rfind(missing + ": cannot open", 0), 0u);
    const std::string missing_glb = (dir_.path() / "missing.glb").string();
    EXPECT_EQ(test::load_error([&] { load_clip(missing_glb); }).rfind(missing_glb + ": cannot open", 0), 0u);
    const std::string folder = (dir_.path() / "folder.bvh").string();
    std::filesystem::create_directory(folder);
    EXPECT_EQ(test::load_error([&] { load_clip(folder); }).rfind(folder + ": cannot open", 0), 0u);
    const std::string fifo = (dir_.path() / "fifo.bvh").string();
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_EQ(test::load_error([&] { load_clip(fifo); }), fifo + ": cannot open: not a regular file");
    const std::string text = write("clip.txt", walk_bvh(3, 0, 170, 40));
    EXPECT_EQ(test::load_error([&] { load_clip(text); }).rfind(text + ": unknown file type '.txt'", 0), 0u);
    const std::string none = write("clip", "");
    EXPECT_EQ(test::load_error([&] { load_clip(none); }).rfind(none + ": unknown file type", 0), 0u);
    const std::string empty = write("empty.bvh", "");
    EXPECT_EQ(test::load_error([&] { load_clip(empty); }).rfind(empty + ":1: expected HIERARCHY", 0), 0u);
    EXPECT_EQ(load_clip(write("UPPER.BVH", walk_bvh(3, 0, 170, 40))).path.size(), 3u);
}

/// The list the viewer's Open panel filters by: what load_clip takes, and nothing it refuses.
TEST(ClipExtensions, AreWhatLoadClipReads) {
    const std::vector<std::string> exts = clip_extensions();
    for (const char* ext : {".bvh", ".glb", ".gltf", ".fbx", ".dae"})
        EXPECT_TRUE(std::binary_search(exts.begin(), exts.end(), std::string(ext))) << ext;
    EXPECT_TRUE(std::is_sorted(exts.begin(), exts.end()));
    EXPECT_EQ(std::adjacent_find(exts.begin(), exts.end()), exts.end());
    for (const std::string& ext : exts) {
        EXPECT_TRUE(is_clip_file("dir/clip" + ext)) << ext;
        std::string upper = ext;
        for (char& c : upper) c = char(std::toupper(static_cast<unsigned char>(c)));
        EXPECT_TRUE(is_clip_file("CLIP" + upper)) << upper;
    }
    for (const char* file : {"clip.txt", "clip.csv", "scene.json", "README.md", "clip", "bvh", "dir.bvh/clip"})
        EXPECT_FALSE(is_clip_file(file)) << file;
}

TEST(DataDir, PrefersAnExistingMobbData) {
    const char* old = std::getenv("MOBB_DATA");
    const std::string saved = old ? old : "";
    const test::TempDir dir;
    ::setenv("MOBB_DATA", dir.path().c_str(), 1);
    EXPECT_EQ(data_dir(), dir.path().lexically_normal().string());
    ::setenv("MOBB_DATA", (dir.path() / "nope").c_str(), 1);
    EXPECT_NE(data_dir(), (dir.path() / "nope").string());
    if (old)
        ::setenv("MOBB_DATA", saved.c_str(), 1);
    else
        ::unsetenv("MOBB_DATA");
}

// Data files named relative to the data folder resolve under it, and back.
TEST(DataDir, ResolvesAndRelativisesDataFiles) {
    const char* old = std::getenv("MOBB_DATA");
    const std::string saved = old ? old : "";
    const test::TempDir dir;
    ::setenv("MOBB_DATA", dir.path().c_str(), 1);
    const std::string file = resolve_data_file("cmu/x.bvh");
    EXPECT_EQ(file, (dir.path() / "cmu/x.bvh").string());
    EXPECT_EQ(data_relative(file), "cmu/x.bvh");
    EXPECT_EQ(resolve_data_file("/abs/y.bvh"), "/abs/y.bvh");
    EXPECT_EQ(data_relative("/elsewhere/y.bvh"), "/elsewhere/y.bvh");
    if (old)
        ::setenv("MOBB_DATA", saved.c_str(), 1);
    else
        ::unsetenv("MOBB_DATA");
}

// Loader options as written on the command line and in scene files; errors name the option.
TEST(LoadOptionText, ParsesOrNamesTheOption) {
    LoadOptionText t;
    t.up = "z";
    t.scale = "0.01";
    t.frames = "5:20";
    t.fps = 30;
    t.animation = "Take 001";
    t.root = "Hips";
    const LoadOptions o = parse_load_options(t);
    EXPECT_EQ(o.up, UpAxis::Z);
    EXPECT_EQ(o.animation, "Take 001");
    EXPECT_EQ(o.root, "Hips");
    EXPECT_EQ(*o.scale, 0.01);
    EXPECT_EQ(o.frame_begin, 5);
    EXPECT_EQ(o.frame_end, 20);
    EXPECT_EQ(*o.fps, 30.0);
    EXPECT_FALSE(parse_load_options({}).scale.has_value());
    EXPECT_EQ(parse_load_options({"y", "auto", "7:", 0, 0, "", ""}).frame_end, -1);
    const auto error = [](LoadOptionText x) {
        try {
            parse_load_options(x);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_EQ(error({"w", "auto", "", 0, 0, "", ""}).rfind("--up:", 0), 0u);
    EXPECT_EQ(error({"y", "-1", "", 0, 0, "", ""}), "--scale: must be positive");
    EXPECT_EQ(error({"y", "1cm", "", 0, 0, "", ""}), "--scale: '1cm' is not a finite number");
    EXPECT_EQ(error({"y", "auto", "5:2", 0, 0, "", ""}), "--frames: expected whole numbers 0 <= A < B, got '5:2'");
    EXPECT_EQ(error({"y", "auto", "5", 0, 0, "", ""}), "--frames: expected A:B, got '5'");
}

}  // namespace
}  // namespace mobb::io
