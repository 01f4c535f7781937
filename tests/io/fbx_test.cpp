// FBX through Assimp: small ASCII FBX files written here (key times, interpolation, units, axes, --root,
// --animation, errors), then the real FBX exports of the CMU clips against their NAME.path.csv references
// and the BVH files they came from (skipped without the data, failed without it when MOBB_REQUIRE_DATA=1).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ascii_fbx.h"
#include "fbx_scan.h"
#include "mobb/io/assimp_reader.h"
#include "mobb/io/load.h"
#include "test_util.h"

namespace mobb::io {
namespace {

class Fbx : public ::testing::Test {
protected:
    std::string write(const test::AsciiFbx& f, const std::string& name = "clip.fbx") {
        return dir_.write(name, test::ascii_fbx(f));
    }
    test::TempDir dir_;
};

test::AsciiFbx walk(std::vector<double> seconds, std::vector<double> x) {
    test::AsciiFbx f;
    f.key_seconds = std::move(seconds);
    f.key_x = std::move(x);
    return f;
}

bool one_line(const std::string& s) { return !s.empty() && s.find('\n') == std::string::npos; }

TEST_F(Fbx, KeysOnTheFrameGridAreTheSamplesWithTheFilesUnitAndRate) {
    // 30 fps; keys at frames 0, 1, 3 (sparse but on the grid): frame 2 is interpolated, no warning.
    const Clip clip = load_clip(write(walk({0, 1 / 30.0, 3 / 30.0}, {0, 0.1, 0.4})));
    EXPECT_TRUE(clip.warnings.empty()) << clip.warnings.front();
    ASSERT_EQ(clip.path.size(), 4u);
    EXPECT_EQ(clip.path.dt, 1.0 / 30.0);
    EXPECT_EQ(clip.scale, 1.0);  // UnitScaleFactor 100: metres
    EXPECT_EQ(clip.scale_reason, "FBX UnitScaleFactor 100: metres");
    const double x[] = {0, 0.1, 0.25, 0.4};
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_NEAR(clip.path.samples[i].x, x[i], 1e-6) << i;  // keys are float32
        EXPECT_NEAR(clip.path.samples[i].y, 0, 1e-12) << i;
        EXPECT_NEAR(clip.path.samples[i].r, 0.5, 1e-9) << i;  // the hand, 0.5 m along X
    }
    const Skeleton& s = clip.animation.skeleton;
    EXPECT_EQ(s.names, (std::vector<std::string>{"hips", "hand"}));
    EXPECT_EQ(s.parents, (std::vector<int>{-1, 0}));
    EXPECT_EQ(s.root, 0);
    EXPECT_NEAR(clip.animation.at(2, 1).y, 1.0, 1e-9);  // hips height, Y up
}

TEST_F(Fbx, UnevenKeysAreResampledOnTheGridSayingSo) {
    // Keys at 0, 1.5 and 3 frames of 30 fps: samples at every frame, interpolated between the keys.
    const Clip clip = load_clip(write(walk({0, 0.05, 0.1}, {0, 0.1, 0.3})));
    ASSERT_EQ(clip.warnings.size(), 1u);
    EXPECT_NE(clip.warnings[0].find("1 of 3 key times are off the 0.0333333 s grid; resampled on it"),
              std::string::npos)
        << clip.warnings[0];
    EXPECT_EQ(clip.warnings[0].rfind(clip.file + ": animation 'walk'", 0), 0u) << clip.warnings[0];
    ASSERT_EQ(clip.path.size(), 4u);
    const double x[] = {0, 0.2 / 3, 0.5 / 3, 0.3};
    for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(clip.path.samples[i].x, x[i], 1e-6) << i;
}

TEST_F(Fbx, DenserKeysThanTheFrameRateSetTheSpacing) {
    test::AsciiFbx f = walk({0, 0.01, 0.02, 0.03}, {0, 0.1, 0.2, 0.3});  // 100 Hz keys in a 30 fps file
    const Clip clip = load_clip(write(f));
    EXPECT_TRUE(clip.warnings.empty());
    ASSERT_EQ(clip.path.size(), 4u);
    EXPECT_EQ(clip.path.dt, 0.01);
    EXPECT_NEAR(clip.path.samples[3].x, 0.3, 1e-6);
}

TEST_F(Fbx, UnitScaleFactorAndScaleOption) {
    test::AsciiFbx f = walk({0, 1 / 30.0}, {0, 40});
    f.unit_cm = 1;  // centimetres
    f.hips_height = 100;
    f.reach = 50;
    const std::string file = write(f);
    const Clip cm = load_clip(file);
    EXPECT_EQ(cm.scale, 0.01);
    EXPECT_EQ(cm.scale_reason, "FBX UnitScaleFactor 1: centimetres");
    EXPECT_NEAR(cm.path.samples[1].x, 0.4, 1e-6);
    EXPECT_NEAR(cm.path.samples[1].r, 0.5, 1e-9);
    LoadOptions o;
    o.scale = 0.001;
    const Clip given = load_clip(file, o);
    EXPECT_EQ(given.scale_reason, "given: 0.001 m per unit");
    EXPECT_NEAR(given.path.samples[1].x, 0.04, 1e-6);
    // No UnitScaleFactor: guessed from the standing height, like BVH (a 170-unit span: centimetres).
    f.unit_cm = 0;
    f.hips_height = 0;
    f.reach = 170;
    const Clip guessed = load_clip(write(f));
    EXPECT_EQ(guessed.scale, 0.01);
    EXPECT_EQ(guessed.scale_reason, "auto: centimetres (standing height 170.0 units)");
    EXPECT_NEAR(guessed.path.samples[1].r, 1.7, 1e-6);
}

TEST_F(Fbx, ZUpFilesKeepTheirGroundPlane) {
    test::AsciiFbx f = walk({0, 1 / 30.0}, {0, 0.2});
    f.up_axis = 2;
    const Clip z = load_clip(write(f));
    EXPECT_EQ(z.up, UpAxis::Z);
    EXPECT_NEAR(z.animation.at(0, 0).z, 1.0, 1e-9);  // hips height along Z
    EXPECT_NEAR(z.path.samples[1].x, 0.2, 1e-6);
    EXPECT_NEAR(z.path.samples[1].r, 0.5, 1e-9);
    // A Y-up file read with --up z keeps its own axis, with a warning.
    LoadOptions o;
    o.up = UpAxis::Z;
    const Clip y = load_clip(write(walk({0, 1 / 30.0}, {0, 0.2})), o);
    EXPECT_EQ(y.up, UpAxis::Y);
    ASSERT_EQ(y.warnings.size(), 1u);
    EXPECT_NE(y.warnings[0].find("--up z is ignored"), std::string::npos) << y.warnings[0];
    // No UpAxis in the file: --up decides, as for BVH.
    test::AsciiFbx unstated = walk({0, 1 / 30.0}, {0, 0.2});
    unstated.up_axis = 2;
    unstated.write_up = false;
    const std::string unstated_file = write(unstated, "unstated.fbx");
    const Clip z_given = load_clip(unstated_file, o);
    EXPECT_EQ(z_given.up, UpAxis::Z);
    EXPECT_TRUE(z_given.warnings.empty());
    EXPECT_NEAR(z_given.path.samples[1].r, 0.5, 1e-9);
    EXPECT_EQ(load_clip(unstated_file).up, UpAxis::Y);
    // X up is turned to Y up: the keyed X becomes the height, and the hand (along X) is straight above.
    f.up_axis = 0;
    const Clip x = load_clip(write(f));
    EXPECT_EQ(x.up, UpAxis::Y);
    EXPECT_NEAR(x.animation.at(1, 0).y, 0.2, 1e-6);
    EXPECT_NEAR(x.animation.at(1, 1).y, 0.7, 1e-6);
    EXPECT_NEAR(x.path.samples[1].x, 0, 1e-9);
    EXPECT_NEAR(x.path.samples[1].y, 0, 1e-9);
    EXPECT_NEAR(x.path.samples[1].r, 0, 1e-9);
}

TEST_F(Fbx, RootAndAnimationOptions) {
    const std::string file = write(walk({0, 1 / 30.0}, {0, 0.2}));
    LoadOptions o;
    o.root = "hand";
    const Clip hand = load_clip(file, o);
    EXPECT_EQ(hand.animation.skeleton.root, 1);
    EXPECT_NEAR(hand.path.samples[1].x, 0.7, 1e-6);
    EXPECT_NEAR(hand.path.samples[1].r, 0.5, 1e-9);
    o.root = "foot";
    const std::string message = test::load_error([&] { load_clip(file, o); });
    EXPECT_EQ(message, file + ": --root: no joint named 'foot' (the skeleton's root is 'hips')");

    o = {};
    o.animation = "walk";
    EXPECT_EQ(load_clip(file, o).path.size(), 2u);
    o.animation = "run";
    EXPECT_EQ(test::load_error([&] { load_clip(file, o); }), file + ": no animation named 'run' (the file has 'walk')");
}

TEST_F(Fbx, RootOptionWorksForBvhToo) {
    const std::string bvh =
        dir_.write("w.bvh",
                   "HIERARCHY\nROOT hips\n{\n\tOFFSET 0 0 0\n\tCHANNELS 3 Xposition Yposition Zposition\n"
                   "\tJOINT hand\n\t{\n\t\tOFFSET 30 0 0\n\t\tCHANNELS 3 Zrotation Xrotation Yrotation\n"
                   "\t\tEnd Site\n\t\t{\n\t\t\tOFFSET 0 170 0\n\t\t}\n\t}\n}\nMOTION\nFrames: 2\nFrame Time: 0.016667\n"
                   "0 0 0 0 0 0\n10 0 0 0 0 0\n");
    LoadOptions o;
    o.root = "hand";
    const Clip clip = load_clip(bvh, o);
    EXPECT_NEAR(clip.path.samples[1].x, 0.4, 1e-9);  // (10 + 30) cm
    EXPECT_NEAR(clip.path.samples[1].r, 0.3, 1e-9);  // to the hips
}

TEST_F(Fbx, MalformedFilesAreOneLineErrors) {
    // No animation, no skeleton (only an FBX null moves), wrong magic, a cut ASCII file, an empty file.
    test::AsciiFbx still;
    const std::string no_animation = write(still, "still.fbx");
    EXPECT_EQ(test::load_error([&] { load_clip(no_animation); }), no_animation + ": the file has no animation");

    test::AsciiFbx null = walk({0, 1 / 30.0}, {0, 1});
    null.null_only = true;
    const std::string no_skeleton = write(null, "null.fbx");
    const std::string skeleton_error = test::load_error([&] { load_clip(no_skeleton); });
    EXPECT_EQ(skeleton_error.rfind(no_skeleton + ": no skeleton: ", 0), 0u) << skeleton_error;

    std::string binary = "Kaydara FBX Binarx  ";
    binary += std::string("\0\x1a\0\xe8\x1c\0\0", 7) + std::string(200, '\x01');
    const std::string magic = dir_.write("magic.fbx", binary);
    const std::string cut_text = test::ascii_fbx(walk({0, 1 / 30.0}, {0, 1}));
    const std::string cut = dir_.write("cut.fbx", cut_text.substr(0, cut_text.size() / 2));
    const std::string empty = dir_.write("empty.fbx", "");
    for (const std::string& file : {magic, cut, empty}) {
        const std::string message = test::load_error([&] { load_clip(file); });
        EXPECT_EQ(message.rfind(file + ": ", 0), 0u) << message;
        EXPECT_TRUE(one_line(message)) << message;
    }
    for (const std::string& m : {skeleton_error}) EXPECT_TRUE(one_line(m)) << m;

    // A model connected to itself: Assimp 5.2 would recurse until the stack overflows.
    std::string looped = test::ascii_fbx(walk({0, 1 / 30.0}, {0, 0.1}));
    const std::string link = "C: \"OO\",1002,1001";
    ASSERT_NE(looped.find(link), std::string::npos);
    looped.replace(looped.find(link), link.size(), "C: \"OO\",1002,1002");
    const std::string cycle = dir_.write("cycle.fbx", looped);
    EXPECT_EQ(test::load_error([&] { load_clip(cycle); }),
              cycle + ": FBX connections form a cycle through object 1002");

    // The same loop through ids with junk after their digits, which Assimp reads as the digits (found by
    // fuzz/fbx_fuzz in CI: a stack overflow in Assimp).
    std::string junk = test::ascii_fbx(walk({0, 1 / 30.0}, {0, 0.1}));
    junk.replace(junk.find(link), link.size(), "C: \"OO\",1002,1001yy\n\tC: \"OO\",1001,1002C");
    const std::string junk_cycle = dir_.write("junk_cycle.fbx", junk);
    EXPECT_EQ(test::load_error([&] { load_clip(junk_cycle); }),
              junk_cycle + ": FBX connections form a cycle through object 1001");

    // An array declaring more values than the file could hold: Assimp would reserve them all first (found
    // by fuzz/fbx_fuzz in CI: 77,777,777,773 key times, 622 GB). A declared length the file holds loads.
    std::string huge = test::ascii_fbx(walk({0, 1 / 30.0}, {0, 0.1}));
    const std::size_t star = huge.find("KeyTime: *");
    ASSERT_NE(star, std::string::npos);
    const std::size_t digits = star + std::string("KeyTime: *").size();
    huge.replace(digits, huge.find_first_not_of("0123456789", digits) - digits, "77777777773");
    const std::string oversized = dir_.write("oversized.fbx", huge);
    EXPECT_EQ(test::load_error([&] { load_clip(oversized); }),
              oversized + ": an FBX array declares more values than the file's " + std::to_string(huge.size()) +
                  " bytes can hold");
}

// A binary FBX 7400 of one record "KeyValueFloat" holding one array property (type 'd'): `length` values,
// `encoding` (0 plain, 1 zlib), `bytes` bytes of data (zeros: only their count matters here).
std::string binary_array(std::uint32_t length, std::uint32_t encoding, std::uint32_t bytes) {
    const auto u32 = [](std::uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
    const std::string name = "KeyValueFloat";
    const std::string props = "d" + u32(length) + u32(encoding) + u32(bytes) + std::string(bytes, '\0');
    std::string out = std::string("Kaydara FBX Binary  \0\x1a\0", 23) + u32(7400);
    const auto end = std::uint32_t(out.size() + 13 + name.size() + props.size());
    out += u32(end) + u32(1) + u32(std::uint32_t(props.size())) + char(name.size()) + name + props;
    return out + std::string(13, '\0');  // the null record closing the list
}

TEST_F(Fbx, ABinaryArrayDeflateCannotFillIsRefusedBeforeAssimpAllocatesIt) {
    // A zlib array of 536,870,911 doubles (4 GB) in 10 compressed bytes: Assimp would allocate it all.
    EXPECT_EQ(fbx::hazards(binary_array(0x1fffffff, 1, 10)).impossible_array, 0x1fffffffu);
    // 1,000 doubles (8,000 bytes) from 10 compressed bytes is within deflate's 1,032 to 1 (and its frame).
    EXPECT_FALSE(fbx::hazards(binary_array(1000, 1, 10)).impossible_array.has_value());
    // A plain array's length Assimp checks against its bytes itself; an empty record list holds nothing.
    EXPECT_FALSE(fbx::hazards(binary_array(0x1fffffff, 0, 10)).impossible_array.has_value());
    EXPECT_FALSE(
        fbx::hazards(std::string("Kaydara FBX Binary  \0\x1a\0\xe8\x1c\0\0", 27)).impossible_array.has_value());

    const std::string bomb = binary_array(0x1fffffff, 1, 10);
    const std::string file = dir_.write("bomb.fbx", bomb);
    EXPECT_EQ(test::load_error([&] { load_clip(file); }), file +
                                                              ": an FBX array declares more values than the file's " +
                                                              std::to_string(bomb.size()) + " bytes can hold");
}

// A binary FBX 7500 (64-bit record words) of one record whose property list declares `length` bytes and
// holds none.
std::string binary_overrun(std::uint64_t length) {
    const auto u64 = [](std::uint64_t v) { return std::string(reinterpret_cast<const char*>(&v), 8); };
    const std::uint32_t version = 7500;
    const std::string name = "KeyVer";
    std::string out =
        std::string("Kaydara FBX Binary  \0\x1a\0", 23) + std::string(reinterpret_cast<const char*>(&version), 4);
    const std::uint64_t end = out.size() + 25 + name.size();
    out += u64(end) + u64(1) + u64(length) + char(name.size()) + name;
    return out + std::string(25, '\0');  // the null record closing the list
}

TEST_F(Fbx, ABinaryRecordRunningPastTheFileIsRefusedBeforeAssimpReadsIt) {
    // A length near 2^64 wraps Assimp's pointer past the end, and its assertion aborts (found by
    // fuzz/fbx_fuzz in CI); a shorter overrun is refused the same way; the 27-byte header holds no record.
    EXPECT_EQ(fbx::hazards(binary_overrun(0xffffffff6c756166)).overrun, 27u);
    EXPECT_EQ(fbx::hazards(binary_overrun(1000)).overrun, 27u);
    EXPECT_FALSE(fbx::hazards(binary_overrun(0)).overrun.has_value());
    EXPECT_FALSE(fbx::hazards(binary_array(1000, 1, 10)).overrun.has_value());
    // Assimp reads a file as binary on the magic's first 18 bytes (found by fuzz/fbx_fuzz: a mutated space).
    std::string unspaced = binary_overrun(0xffffffff6c756166);
    unspaced[18] = '\x1b';
    EXPECT_EQ(fbx::hazards(unspaced).overrun, 27u);
    // Assimp reads the file with a NUL after it, so a record may end one byte past the file (found by
    // fuzz/fbx_fuzz in CI): without the null record, the first one ends there.
    std::string short_of_nul = binary_overrun(0xffffffff6c756166);
    short_of_nul.resize(short_of_nul.size() - 25);
    const std::uint64_t past = short_of_nul.size() + 1;
    std::memcpy(&short_of_nul[27], &past, sizeof past);
    EXPECT_EQ(fbx::hazards(short_of_nul).overrun, 27u);

    const std::string wrap = binary_overrun(0xffffffff6c756166);
    const std::string file = dir_.write("wrap.fbx", wrap);
    EXPECT_EQ(test::load_error([&] { load_clip(file); }),
              file + ": the FBX record at byte 27 declares more property bytes than the file holds");
}

// Collada through the same reader: a Z-up file in centimetres (Assimp turns it Y-up and to metres), two
// joints under an armature node, the hips' X keyed at 30 Hz.
TEST_F(Fbx, ColladaGoesThroughTheSameReader) {
    const std::string dae = dir_.write("walk.dae", R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="centimeter" meter="0.01"/><up_axis>Z_UP</up_axis></asset>
  <library_animations>
    <animation id="hips_x">
      <source id="t"><float_array id="t-array" count="3">0 0.0333333 0.0666667</float_array>
        <technique_common><accessor source="#t-array" count="3" stride="1"><param name="TIME" type="float"/></accessor></technique_common></source>
      <source id="v"><float_array id="v-array" count="3">0 10 40</float_array>
        <technique_common><accessor source="#v-array" count="3" stride="1"><param name="X" type="float"/></accessor></technique_common></source>
      <sampler id="s"><input semantic="INPUT" source="#t"/><input semantic="OUTPUT" source="#v"/></sampler>
      <channel source="#s" target="hips/location.X"/>
    </animation>
  </library_animations>
  <library_visual_scenes>
    <visual_scene id="Scene">
      <node id="Armature" name="Armature" type="NODE">
        <node id="hips" name="hips" sid="hips" type="JOINT"><translate sid="location">0 0 100</translate>
          <node id="hand" name="hand" sid="hand" type="JOINT"><translate sid="location">0 50 0</translate></node>
        </node>
      </node>
    </visual_scene>
  </library_visual_scenes>
  <scene><instance_visual_scene url="#Scene"/></scene>
</COLLADA>
)");
    const Clip clip = load_clip(dae);
    EXPECT_EQ(clip.animation.skeleton.names, (std::vector<std::string>{"hips", "hand"}));
    EXPECT_EQ(clip.path.dt, 1.0 / 30.0);
    EXPECT_EQ(clip.up, UpAxis::Y);
    EXPECT_EQ(clip.scale_reason.rfind("auto: metres", 0), 0u) << clip.scale_reason;  // Collada states no FBX unit
    ASSERT_EQ(clip.path.size(), 3u);
    const double x[] = {0, 0.1, 0.4};
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_NEAR(clip.path.samples[i].x, x[i], 1e-6) << i;
        EXPECT_NEAR(clip.path.samples[i].y, 0, 1e-6) << i;
        EXPECT_NEAR(clip.path.samples[i].r, 0.5, 1e-6) << i;
    }
    EXPECT_NEAR(clip.animation.at(0, 0).y, 1.0, 1e-6);  // the hips 1 m up once turned Y-up
}

TEST(AssimpReader, ReadsFbxAndColladaButNotText) {
    EXPECT_TRUE(assimp::reads(".fbx"));
    EXPECT_TRUE(assimp::reads(".FBX"));
    EXPECT_TRUE(assimp::reads(".dae"));
    EXPECT_FALSE(assimp::reads(".txt"));
    EXPECT_FALSE(assimp::reads("fbx"));
    EXPECT_FALSE(assimp::reads(""));
}

// ---- The real FBX exports (data/fbx) ----

const char* const kFbxClips[] = {"002_01", "002_03", "005_01", "006_02", "007_01", "007_02"};

std::string fbx_dir() {
    const std::string dir = test::mocap_dir();
    std::error_code ec;
    return !dir.empty() && std::filesystem::is_directory(dir + "/fbx", ec) ? dir + "/fbx" : std::string();
}

#define MOBB_NEED_FBX(dir)                                                                            \
    const std::string dir = fbx_dir();                                                                \
    if (dir.empty()) {                                                                                \
        if (::mobb::test::data_required()) FAIL() << "fbx/: " << ::mobb::test::missing_data_reason(); \
        GTEST_SKIP() << "fbx/: " << ::mobb::test::missing_data_reason();                              \
    }

// NAME.path.csv: frame,x,y,r in metres.
std::vector<Sample> reference(const std::string& file) {
    std::ifstream in(file);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "frame,x,y,r") << file;
    std::vector<Sample> out;
    while (std::getline(in, line)) {
        std::replace(line.begin(), line.end(), ',', ' ');
        std::istringstream row(line);
        int frame = 0;
        Sample s;
        row >> frame >> s.x >> s.y >> s.r;
        EXPECT_EQ(frame, int(out.size())) << file;
        out.push_back(s);
    }
    return out;
}

class RealFbx : public ::testing::TestWithParam<const char*> {};

TEST_P(RealFbx, PathMatchesItsReferenceAndRootPathTheBvh) {
    MOBB_NEED_FBX(dir);
    const std::string name = GetParam();
    const Clip fbx = load_clip(dir + "/" + name + ".fbx");
    const Clip bvh = load_clip(dir + "/../cmu/" + name + ".bvh");
    const std::vector<Sample> ref = reference(dir + "/" + name + ".path.csv");
    ASSERT_EQ(fbx.path.size(), ref.size());
    ASSERT_EQ(fbx.path.size(), bvh.path.size());
    EXPECT_EQ(fbx.path.dt, 1.0 / 60.0);
    EXPECT_EQ(fbx.scale, 0.01);
    EXPECT_EQ(fbx.scale_reason, "FBX UnitScaleFactor 1: centimetres");
    EXPECT_TRUE(fbx.warnings.empty()) << fbx.warnings.front();
    const Skeleton& s = fbx.animation.skeleton;
    EXPECT_EQ(s.names[std::size_t(s.root)], bvh.animation.skeleton.names[std::size_t(bvh.animation.skeleton.root)]);
    EXPECT_GE(s.size(), 141);  // the README: 141-142 bone nodes, leaf bones included
    EXPECT_LE(s.size(), 142);
    double worst_ref = 0, worst_bvh = 0, worst_r = 0, r_below_bvh = 0;
    for (std::size_t i = 0; i < ref.size(); ++i) {
        const Sample& p = fbx.path.samples[i];
        const Sample& b = bvh.path.samples[i];
        worst_ref = std::max({worst_ref, std::abs(p.x - ref[i].x), std::abs(p.y - ref[i].y)});
        worst_r = std::max(worst_r, std::abs(p.r - ref[i].r));
        worst_bvh = std::max(worst_bvh, std::hypot(p.x - b.x, p.y - b.y));
        r_below_bvh = std::max(r_below_bvh, b.r - p.r);
    }
    RecordProperty("worst_path_vs_csv_mm", std::to_string(worst_ref * 1e3));
    RecordProperty("worst_r_vs_csv_mm", std::to_string(worst_r * 1e3));
    RecordProperty("worst_root_vs_bvh_mm", std::to_string(worst_bvh * 1e3));
    EXPECT_LT(worst_ref, 1e-3) << name;
    EXPECT_LT(worst_r, 1e-3) << name;
    EXPECT_LT(worst_bvh, 1e-3) << name;
    EXPECT_LT(r_below_bvh, 1e-3) << name << ": leaf bones only add to the BVH's r";
}

INSTANTIATE_TEST_SUITE_P(Data, RealFbx, ::testing::ValuesIn(kFbxClips),
                         [](const ::testing::TestParamInfo<const char*>& p) { return std::string("fbx_") + p.param; });

TEST(RealFbxOptions, AnimationRootFramesAndFps) {
    MOBB_NEED_FBX(dir);
    const std::string file = dir + "/002_01.fbx";
    const Clip full = load_clip(file);
    LoadOptions o;
    o.animation = "Scene";
    o.root = "CC_Base_Hip";
    o.frame_begin = 10;
    o.frame_end = 40;
    o.fps = 30;
    const Clip part = load_clip(file, o);
    ASSERT_EQ(part.path.size(), 15u);
    const int hip = part.animation.skeleton.root;
    EXPECT_EQ(part.animation.skeleton.names[std::size_t(hip)], "CC_Base_Hip");
    for (std::size_t k = 0; k < part.path.size(); ++k) {
        const glm::dvec3 p = full.animation.at(10 + 2 * int(k), hip);
        EXPECT_DOUBLE_EQ(part.path.samples[k].x, p.x);
        EXPECT_DOUBLE_EQ(part.path.samples[k].y, -p.z);
    }
    o = {};
    o.animation = "Take 001";
    EXPECT_EQ(test::load_error([&] { load_clip(file, o); }),
              file + ": no animation named 'Take 001' (the file has 'Scene')");
}

TEST(RealFbxErrors, TruncatedAndLoopedCopiesAreOneLineErrors) {
    MOBB_NEED_FBX(dir);
    const test::TempDir tmp;
    std::ifstream in(dir + "/002_03.fbx", std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string bytes = ss.str();
    for (const std::size_t keep : {bytes.size() / 2, std::size_t(100), std::size_t(20)}) {
        const std::string cut = tmp.write("cut.fbx", bytes.substr(0, keep));
        const std::string message = test::load_error([&] { load_clip(cut); });
        EXPECT_EQ(message.rfind(cut + ": ", 0), 0u) << message;
        EXPECT_TRUE(one_line(message)) << message;
    }
    // The binary file with its first connection turned into a loop (destination := source).
    // A "C" record: name length 1, "C", then the properties S "OO", L source, L destination.
    const std::string record(
        "\x01"
        "CS\x02\0\0\0OOL",
        10);
    const std::size_t at = bytes.find(record);
    ASSERT_NE(at, std::string::npos);
    ASSERT_EQ(bytes[at + 18], 'L');
    std::string looped = bytes;
    looped.replace(at + 19, 8, bytes.substr(at + 10, 8));
    const std::string cycle = tmp.write("cycle.fbx", looped);
    const std::string message = test::load_error([&] { load_clip(cycle); });
    EXPECT_EQ(message.rfind(cycle + ": FBX connections form a cycle through object ", 0), 0u) << message;
}

}  // namespace
}  // namespace mobb::io
