// The command line as a user meets it: exit codes 0 / 1 / 2, data on stdout only on success.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "data.h"
#include "files.h"
#include "run.h"

namespace {

using mobb::test::Result;
using mobb::test::slurp;
using mobb::test::temp_file;

Result mobb(const std::string& args, const std::string& input = "") { return mobb::test::run_mobb(args, input); }

std::string cmu(const std::string& name) { return mobb::test::data_file("cmu/" + name); }

std::string write_temp(const std::string& name, const std::string& text) {
    const std::string path = temp_file(name);
    std::ofstream(path) << text;
    return path;
}

int count_lines(const std::string& s) { return int(std::count(s.begin(), s.end(), '\n')); }

TEST(CliTest, UsageErrorsExitTwo) {
    EXPECT_EQ(mobb("").code, 2);
    EXPECT_EQ(mobb("frobnicate").code, 2);
    EXPECT_EQ(mobb("query onlyone.bvh --place-a 0,0,0,0 --place-b 0,0,0,0").code, 2);
    EXPECT_EQ(mobb("tree x.bvh --tree octree").code, 2);
    EXPECT_EQ(mobb("path x.bvh --up w").code, 2);
}

TEST(CliTest, EverySubcommandHasHelp) {
    for (const char* sub : {"info", "path", "tree", "query", "batch"}) {
        const Result r = mobb(std::string(sub) + " --help");
        EXPECT_EQ(r.code, 0) << sub;
        EXPECT_NE(r.out.find("--scale"), std::string::npos) << sub;
    }
}

TEST(CliTest, MissingFileIsBadInputNamingTheFile) {
    const Result r = mobb("info /nonexistent/walk.bvh");
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.out.empty());
    EXPECT_NE(r.err.find("/nonexistent/walk.bvh"), std::string::npos) << r.err;
    EXPECT_EQ(count_lines(r.err), 1) << r.err;
}

TEST(CliTest, MalformedBvhNamesFileAndLine) {
    const std::string bad =
        write_temp("bad.bvh", "HIERARCHY\nROOT Hips\n{\n  OFFSET 0 0 0\n  CHANNELS 7 Xposition\n}\n");
    const Result r = mobb("path " + bad);
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.out.empty());
    EXPECT_NE(r.err.find(bad + ":5"), std::string::npos) << r.err;
}

TEST(CliTest, InfoReportsTheRealClip) {
    MOBB_REQUIRE_MOCAP();
    const Result r = mobb("info " + cmu("002_01.bvh"));
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("171 samples"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("60.000 Hz"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("root RL_BoneRoot"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("centimetres"), std::string::npos) << r.out;
    EXPECT_NE(r.err.find("centimetres"), std::string::npos) << "the scale chosen is printed: " << r.err;
}

TEST(CliTest, PathIsCsvInSecondsAndMetres) {
    MOBB_REQUIRE_MOCAP();
    const Result r = mobb("path " + cmu("002_01.bvh"));
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.out.rfind("t,x,y,r\n", 0), 0u);
    EXPECT_EQ(count_lines(r.out), 172);
    const Result part = mobb("path " + cmu("002_01.bvh") + " --frames 10:20 --fps 30");
    ASSERT_EQ(part.code, 0) << part.err;
    EXPECT_EQ(count_lines(part.out), 6);  // frames 10..19 at 60 Hz -> 5 samples at 30 Hz
    // Row 2 of the resampled path is frame 14 of the file: row 5 of the 10:20 cut at full rate.
    const Result full = mobb("path " + cmu("002_01.bvh") + " --frames 10:20");
    std::istringstream a(part.out), b(full.out);
    std::string la, lb;
    for (int i = 0; i < 4; ++i) std::getline(a, la);
    for (int i = 0; i < 6; ++i) std::getline(b, lb);
    EXPECT_EQ(la.substr(la.find(',')), lb.substr(lb.find(',')));
}

TEST(CliTest, TreeOfATwentySecondClipContainsEveryCylinder) {
    MOBB_REQUIRE_MOCAP();
    for (const char* type : {"mobb", "umobb"}) {
        const Result r = mobb("tree " + cmu("001_08.bvh") + " --tree " + type);  // 21.75 s
        ASSERT_EQ(r.code, 0) << r.err;
        EXPECT_NE(r.out.find("all sample cylinders contained: yes"), std::string::npos) << r.out;
        EXPECT_NE(r.out.find("depth 9"), std::string::npos) << r.out;  // 1305 samples, n_min 10
        const Result j = mobb("tree " + cmu("001_08.bvh") + " --json --nmin 20 --tree " + type);
        ASSERT_EQ(j.code, 0) << j.err;
        const auto doc = nlohmann::json::parse(j.out);
        EXPECT_TRUE(doc["contained"].get<bool>());
        EXPECT_EQ(doc["levels"].size(), 8u);
        EXPECT_EQ(doc["levels"][3]["nodes"].get<int>(), 8);
    }
}

TEST(CliTest, QueryAnswersJsonAndAgreesWithBrute) {
    MOBB_REQUIRE_MOCAP();
    const std::string files = cmu("007_01.bvh") + " " + cmu("002_01.bvh");
    for (const char* place_b : {"1.5,-1.5,90,0.3", "1.5,-1.5,90,30", "0.5,0.2,180,0"}) {
        const std::string args = "query " + files + " --place-a 0,0,0,0 --place-b " + place_b;
        const Result tree = mobb(args);
        const Result brute = mobb(args + " --tree brute");
        ASSERT_EQ(tree.code, 0) << tree.err;
        ASSERT_EQ(brute.code, 0) << brute.err;
        const auto t = nlohmann::json::parse(tree.out), b = nlohmann::json::parse(brute.out);
        EXPECT_EQ(t["collide"], b["collide"]) << place_b;
        for (const char* key : {"collide", "tests2d", "tests3d", "samples"}) EXPECT_TRUE(t.contains(key));
    }
}

TEST(CliTest, BadPlacementIsBadInput) {
    MOBB_REQUIRE_MOCAP();
    const Result r =
        mobb("query " + cmu("007_01.bvh") + " " + cmu("002_01.bvh") + " --place-a 0,0,0 --place-b 0,0,0,0");
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.out.empty());
    EXPECT_NE(r.err.find("--place-a"), std::string::npos) << r.err;
    EXPECT_EQ(
        mobb("query " + cmu("007_01.bvh") + " " + cmu("002_01.bvh") + " --place-a 0,0,nan,0 --place-b 0,0,0,0").code,
        1);
}

TEST(CliTest, BatchAnswersEveryLineInOrder) {
    MOBB_REQUIRE_MOCAP();
    const std::string a = cmu("007_01.bvh"), b = cmu("002_01.bvh");
    std::string input;
    for (const char* tb : {"[1.5,-1.5,90,0.3]", "[1.5,-1.5,90,30]", "[0,0,0,0]"})
        input += "{\"a\": \"" + a + "\", \"b\": \"" + b + "\", \"ta\": [0,0,0,0], \"tb\": " + tb + "}\n";
    const Result r = mobb("batch", input);
    ASSERT_EQ(r.code, 0) << r.err;
    ASSERT_EQ(count_lines(r.out), 3);
    std::istringstream lines(r.out);
    std::string line;
    std::vector<bool> answers;
    while (std::getline(lines, line)) answers.push_back(nlohmann::json::parse(line)["collide"].get<bool>());
    EXPECT_FALSE(answers[1]);  // 30 s later: the clips never share a moment
    EXPECT_TRUE(answers[2]);   // same start, same spot
    // One bad line anywhere: error naming it, nothing on stdout.
    const Result bad = mobb("batch", input + "{\"a\": \"" + a + "\"}\n");
    EXPECT_EQ(bad.code, 1);
    EXPECT_TRUE(bad.out.empty());
    EXPECT_NE(bad.err.find("stdin:4"), std::string::npos) << bad.err;
}

// The queries run on a worker pool; the output is the same, line for line, for any thread count.
TEST(CliTest, BatchOutputDoesNotDependOnThreads) {
    MOBB_REQUIRE_MOCAP();
    const std::string a = cmu("007_01.bvh"), b = cmu("002_01.bvh");
    std::string input;
    for (int k = 0; k < 120; ++k) {  // near and far placements, so answers and work differ per line
        const double x = 0.25 * double(k % 13) - 1.5, y = 0.2 * double(k % 7) - 0.6, t = 0.1 * double(k % 11);
        input += "{\"a\": \"" + (k % 2 ? a : b) + "\", \"b\": \"" + b + "\", \"ta\": [0,0," +
                 std::to_string(k * 17 % 360) + ",0], \"tb\": [" + std::to_string(x) + "," + std::to_string(y) +
                 ",90," + std::to_string(t) + "]}\n";
        if (k % 40 == 0) input += "\n";  // blank lines are skipped
    }
    const Result one = mobb("batch --threads 1", input), three = mobb("batch --threads 3", input);
    ASSERT_EQ(one.code, 0) << one.err;
    ASSERT_EQ(three.code, 0) << three.err;
    EXPECT_EQ(count_lines(one.out), 120);
    EXPECT_EQ(one.out, three.out);
    EXPECT_NE(one.out.find("true"), std::string::npos);
    EXPECT_NE(one.out.find("false"), std::string::npos);
    // The first bad line is still the one reported, whatever the threads.
    const Result bad = mobb("batch --threads 3", input + "{\"a\": 1}\n" + input);
    EXPECT_EQ(bad.code, 1);
    EXPECT_TRUE(bad.out.empty());
    EXPECT_NE(bad.err.find("stdin:" + std::to_string(count_lines(input) + 1)), std::string::npos) << bad.err;
    EXPECT_EQ(mobb("batch --threads 0", input).code, 2);
}

}  // namespace
