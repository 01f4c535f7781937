// FBX on the command line: every subcommand reads the real FBX exports (data/fbx), and malformed FBX
// files (written here at run time: truncated, wrong magic, no animation, no skeleton) exit 1 with one
// line naming the file and nothing on stdout.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "ascii_fbx.h"
#include "data.h"
#include "files.h"
#include "run.h"

namespace {

using mobb::test::Result;

Result mobb(const std::string& args) { return mobb::test::run_mobb(args); }

int count_lines(const std::string& s) { return int(std::count(s.begin(), s.end(), '\n')); }

std::string write_temp(const std::string& name, const std::string& bytes) {
    const std::string path = mobb::test::temp_file(name);
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
}

const char* const kClips[] = {"002_01", "002_03", "005_01", "006_02", "007_01", "007_02"};

// The folder of the FBX exports, or "" (the test is then skipped, or failed under MOBB_REQUIRE_DATA=1).
std::string fbx_folder() {
    const std::string dir = mobb::test::data_file("fbx");
    std::error_code ec;
    return !dir.empty() && std::filesystem::is_directory(dir, ec) ? dir : std::string();
}

#define MOBB_REQUIRE_FBX(dir)                                                                      \
    const std::string dir = fbx_folder();                                                          \
    if (dir.empty()) {                                                                             \
        if (mobb::test::data_required()) FAIL() << "MOBB_REQUIRE_DATA=1 but no mocap fbx/ folder"; \
        GTEST_SKIP() << "mocap fbx/ folder not found: set MOBB_DATA or put it in ../shared/mocap"; \
    }

TEST(FbxCli, EverySubcommandReadsEveryFbxFile) {
    MOBB_REQUIRE_FBX(dir);
    for (const char* name : kClips) {
        const std::string file = dir + "/" + name + ".fbx";
        const Result info = mobb("info " + file);
        ASSERT_EQ(info.code, 0) << name << ": " << info.err;
        const Result bvh = mobb("info " + mobb::test::data_file("cmu/" + std::string(name) + ".bvh"));
        const auto root_of = [](const std::string& out) {
            const std::size_t at = out.find(", root ");
            return at == std::string::npos ? std::string() : out.substr(at, out.find('\n', at) - at);
        };
        EXPECT_EQ(root_of(info.out), root_of(bvh.out)) << name << ": the BVH's root joint";
        EXPECT_FALSE(root_of(info.out).empty()) << info.out;
        EXPECT_NE(info.err.find("FBX UnitScaleFactor 1: centimetres"), std::string::npos) << info.err;
        const Result path = mobb("path " + file);
        ASSERT_EQ(path.code, 0) << name << ": " << path.err;
        std::ifstream csv(dir + "/" + name + ".path.csv");
        const std::string reference((std::istreambuf_iterator<char>(csv)), std::istreambuf_iterator<char>());
        EXPECT_EQ(count_lines(path.out), count_lines(reference)) << name << ": one row per frame, and a header";
        const Result tree = mobb("tree " + file);
        ASSERT_EQ(tree.code, 0) << name << ": " << tree.err;
        EXPECT_NE(tree.out.find("all sample cylinders contained: yes"), std::string::npos) << tree.out;
    }
}

TEST(FbxCli, QueryOnFbxAgreesWithTheBvhItCameFrom) {
    MOBB_REQUIRE_FBX(dir);
    const std::string cmu = mobb::test::data_file("cmu");
    for (const char* place_b : {"1.5,-1.5,90,0.3", "0.6,0.2,180,0", "3,3,45,0"}) {
        const std::string places = " --place-a 0,0,0,0 --place-b " + std::string(place_b);
        const Result fbx = mobb("query " + dir + "/007_01.fbx " + dir + "/002_01.fbx" + places);
        const Result bvh = mobb("query " + cmu + "/007_01.bvh " + cmu + "/002_01.bvh" + places + " --tree brute");
        ASSERT_EQ(fbx.code, 0) << fbx.err;
        ASSERT_EQ(bvh.code, 0) << bvh.err;
        EXPECT_EQ(nlohmann::json::parse(fbx.out)["collide"], nlohmann::json::parse(bvh.out)["collide"]) << place_b;
    }
}

TEST(FbxCli, LoaderOptionsReachTheFbxReader) {
    MOBB_REQUIRE_FBX(dir);
    const std::string file = dir + "/002_01.fbx";
    const Result ok = mobb("path " + file + " --animation Scene --root CC_Base_Hip --frames 0:10");
    ASSERT_EQ(ok.code, 0) << ok.err;
    EXPECT_EQ(count_lines(ok.out), 11);
    const Result animation = mobb("path " + file + " --animation Take");
    EXPECT_EQ(animation.code, 1);
    EXPECT_TRUE(animation.out.empty());
    EXPECT_NE(animation.err.find("no animation named 'Take' (the file has 'Scene')"), std::string::npos)
        << animation.err;
    const Result root = mobb("path " + file + " --root Tail");
    EXPECT_EQ(root.code, 1);
    EXPECT_NE(root.err.find("--root: no joint named 'Tail'"), std::string::npos) << root.err;
}

// `mobb view` without a display renders the clips headless to its --screenshot.
TEST(FbxCli, ViewShowsAnFbxFile) {
    if (!MOBB_HAS_VIEWER) GTEST_SKIP() << "built without the viewer";
    MOBB_REQUIRE_FBX(dir);
    const std::string png = mobb::test::temp_file("view_fbx.png");
    const std::string err = mobb::test::temp_file("view_fbx.err");
    std::filesystem::remove(png);
    const std::string cmd = "env -u DISPLAY -u WAYLAND_DISPLAY GALLIUM_DRIVER=llvmpipe " + std::string(MOBB_EXE) +
                            " view " + dir + "/002_01.fbx " + dir + "/007_01.fbx --screenshot " + png +
                            " --width 320 --height 240 >/dev/null 2>" + err;
    EXPECT_EQ(std::system(cmd.c_str()), 0) << mobb::test::slurp(err);
    EXPECT_GT(std::filesystem::file_size(png), 1000u);
}

// `mobb render` takes clip files as `mobb view` does: FBX exports draw headless, a bad one is named.
TEST(FbxCli, RenderDrawsFbxFiles) {
    if (!MOBB_HAS_VIEWER) GTEST_SKIP() << "built without the viewer";
    MOBB_REQUIRE_FBX(dir);
    const std::string png = mobb::test::temp_file("render_fbx.png");
    std::filesystem::remove(png);
    const Result r =
        mobb("render " + dir + "/002_01.fbx " + dir + "/007_01.fbx --ui --width 320 --height 240 --out " + png);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.out, png + "\n");
    EXPECT_GT(std::filesystem::file_size(png), 1000u);

    const std::string bad = write_temp("render_bad.fbx", "Kaydara FBX Binary  \0\x1a\0");
    const std::string bad_png = mobb::test::temp_file("render_bad.png");
    std::filesystem::remove(bad_png);
    const Result b = mobb("render " + dir + "/002_01.fbx " + bad + " --out " + bad_png);
    EXPECT_EQ(b.code, 1);
    EXPECT_EQ(count_lines(b.err), 1) << b.err;
    EXPECT_NE(b.err.find(bad + ": "), std::string::npos) << b.err;
    EXPECT_FALSE(std::filesystem::exists(bad_png));
}

void expect_bad_input(const std::string& file, const std::string& what) {
    for (const char* sub : {"info", "path", "tree"}) {
        const Result r = mobb(std::string(sub) + " " + file);
        EXPECT_EQ(r.code, 1) << what << " (" << sub << "): " << r.err;
        EXPECT_TRUE(r.out.empty()) << what;
        EXPECT_EQ(count_lines(r.err), 1) << what << ": " << r.err;
        EXPECT_EQ(r.err.rfind("error: " + file + ": ", 0), 0u) << what << ": " << r.err;
    }
}

TEST(FbxCli, MalformedFbxExitsOneWithOneLine) {
    mobb::test::AsciiFbx still;
    expect_bad_input(write_temp("still.fbx", mobb::test::ascii_fbx(still)), "no animation");
    mobb::test::AsciiFbx null;
    null.key_seconds = {0, 0.1};
    null.key_x = {0, 1};
    null.null_only = true;
    expect_bad_input(write_temp("null.fbx", mobb::test::ascii_fbx(null)), "no skeleton");
    expect_bad_input(write_temp("magic.fbx", std::string("Kaydara FBX Binarx  \0\x1a\0", 23) + std::string(64, 'x')),
                     "wrong magic");
    const Result r = mobb("info " + write_temp("still.fbx", mobb::test::ascii_fbx(still)));
    EXPECT_NE(r.err.find("the file has no animation"), std::string::npos) << r.err;
}

TEST(FbxCli, TruncatedRealFbxExitsOneWithOneLine) {
    MOBB_REQUIRE_FBX(dir);
    std::ifstream in(dir + "/002_03.fbx", std::ios::binary);
    std::stringstream bytes;
    bytes << in.rdbuf();
    const std::string whole = bytes.str();
    expect_bad_input(write_temp("half.fbx", whole.substr(0, whole.size() / 2)), "truncated");
}

}  // namespace
