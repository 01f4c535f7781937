// Malformed inputs through the command line: a motion graph, a scenario and a crowd record, each with
// one field broken, are refused with exit 1, one line on stderr naming the file and the field, nothing on
// stdout and no output file.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>

#include <nlohmann/json.hpp>

#include "files.h"
#include "run.h"

namespace mobb {
namespace {

using nlohmann::json;
using test::Result;
using test::temp_file;

const std::string kGraph = std::string(MOBB_SOURCE_DIR) + "/assets/graphs/cmu_locomotion.json";

json read_json(const std::string& file) {
    std::ifstream in(file);
    return json::parse(in);
}

// `file` rewritten as `from` with `edit` applied.
void write_edited(const json& from, const std::string& file, const std::function<void(json&)>& edit) {
    json j = from;
    edit(j);
    std::ofstream(file) << j.dump();
}

// Exit 1, "error: FILE: PLACE...: ..." on one line, nothing on stdout, no file at `out`.
void expect_refused(const Result& r, const std::string& file, const std::string& place, const std::string& out) {
    EXPECT_EQ(r.code, 1) << r.err;
    EXPECT_EQ(r.err.rfind("error: " + file + ": " + place, 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_FALSE(std::filesystem::exists(out)) << out;
}

TEST(InputErrors, GraphFieldsThroughCrowd) {
    const json graph = read_json(kGraph);
    const std::string bad = temp_file("bad_graph.json"), rec = temp_file("bad_graph_record.json");
    // One case a line: clang-format 14 breaks up a short lambda that holds a braced list.
    // clang-format off
    const std::vector<std::pair<std::function<void(json&)>, std::string>> cases = {
        {[](json& j) { j["dt"] = 0; }, "graph.dt: "},
        {[](json& j) { j["dt"] = -0.033; }, "graph.dt: "},
        {[](json& j) { j["fps"] = -30; }, "graph.fps: "},
        {[](json& j) { j["threshold"] = 0; }, "graph.threshold: "},
        {[](json& j) { j["window"] = 0; }, "graph.window: "},
        {[](json& j) { j["sources"][2]["samples"] = 0; }, "graph.sources[2].samples: "},
        {[](json& j) { j["clips"][4]["samples"] = {7, 7}; }, "graph.clips[4].samples: "},
        {[](json& j) { j["clips"][4]["path"][2][2] = -0.5; }, "graph.clips[4].path[2][2]: "},
        {[](json& j) { j["clips"][4]["successors"][0] = 500; }, "graph.clips[4].successors[0]: "},
        {[](json& j) { j["clips"][4]["exit"][2] = 7.0; }, "graph.clips[4].exit[2]: "},
        {[](json& j) { j["clips"][4]["distances"][0] = 1.0; }, "graph.clips[4].distances[0]: "},
    };
    // clang-format on
    for (const auto& [edit, place] : cases) {
        SCOPED_TRACE(place);
        write_edited(graph, bad, edit);
        std::remove(rec.c_str());
        expect_refused(
            test::run_mobb("crowd --quiet --graph " + bad + " --agents 2 --world 10x10 --seconds 2 --record " + rec),
            bad, place, rec);
    }
    std::remove(bad.c_str());
}

TEST(InputErrors, ScenarioFieldsThroughCrowd) {
    const json scenario = json::parse(R"({"name": "x", "world": [0, 0, 12, 12], "time_limit": 10,
        "obstacles": [{"rectangle": [5, 5, 6, 6]}],
        "agents": [{"start": [2, 2], "goal": [10, 10]}, {"start": [10, 2], "goal": [2, 10], "start_time": 1}]})");
    const std::string bad = temp_file("bad_scenario.json"), rec = temp_file("bad_scenario_record.json");
    // One case a line: clang-format 14 breaks up a short lambda that holds a braced list.
    // clang-format off
    const std::vector<std::pair<std::function<void(json&)>, std::string>> cases = {
        {[](json& j) { j["time_limit"] = -5; }, "time_limit: "},
        {[](json& j) { j["time_limit"] = 0; }, "time_limit: "},
        {[](json& j) { j["world"] = {12, 0, 0, 12}; }, "world: "},
        {[](json& j) { j["agents"][1]["start_time"] = -1; }, "agents[1].start_time: "},
        {[](json& j) { j["agents"][1]["start_time"] = 10; }, "agents[1].start_time: "},
        {[](json& j) { j["obstacles"][0]["rectangle"] = {5, 5, 14, 6}; }, "obstacles[0]: "},
        {[](json& j) { j["obstacles"][0]["rectangle"] = {6, 5, 5, 6}; }, "obstacles[0].rectangle: "},
    };
    // clang-format on
    // Scenario places follow the file with a dot: "FILE.time_limit: ...".
    for (const auto& [edit, place] : cases) {
        SCOPED_TRACE(place);
        write_edited(scenario, bad, edit);
        std::remove(rec.c_str());
        const Result r = test::run_mobb("crowd --quiet --graph " + kGraph + " --scenario " + bad + " --record " + rec);
        EXPECT_EQ(r.code, 1) << r.err;
        EXPECT_EQ(r.err.rfind("error: " + bad + "." + place, 0), 0u) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_TRUE(r.out.empty()) << r.out;
        EXPECT_FALSE(std::filesystem::exists(rec));
    }
    std::remove(bad.c_str());
}

#if MOBB_HAS_VIEWER
TEST(InputErrors, RecordFieldsThroughRender) {
    const std::string rec = temp_file("good_record.json");
    const Result made =
        test::run_mobb("crowd --quiet --graph " + kGraph + " --agents 4 --world 10x10 --seconds 3 --record " + rec);
    ASSERT_EQ(made.code, 0) << made.err;
    const json record = read_json(rec);
    std::remove(rec.c_str());
    const std::string bad = temp_file("bad_record.json"), png = temp_file("bad_record.png");
    // One case a line: clang-format 14 breaks up a short lambda that holds a braced list.
    // clang-format off
    const std::vector<std::pair<std::function<void(json&)>, std::string>> cases = {
        {[](json& j) { j["dt"] = 0; }, "dt: "},
        {[](json& j) { j["dt"] = -1; }, "dt: "},
        {[](json& j) { j["frames"] = 0; }, "frames: "},
        {[](json& j) { j["world"] = {10, 0, 0, 10}; }, "world: "},
        {[](json& j) { j["tracks"][1]["samples"].erase(3); }, "tracks[1].samples: "},
        {[](json& j) { j["tracks"][1]["samples"][3][3] = -0.2; }, "tracks[1].samples[3][3]: "},
        {[](json& j) { j["tracks"][1]["clips"][0]["start"] = -4; }, "tracks[1].clips[0].start: "},
        {[](json& j) { j["choices"][0]["agent"] = 4; }, "choices[0].agent: "},
        {[](json& j) { j["choices"][0]["frame"] = 1000000; }, "choices[0].frame: "},
        {[](json& j) { j["tracks"][2]["clips"][0]["clip"] = 4000; }, "tracks[2].clips[0].clip: clip 4000 is not in"},
        {[](json& j) { j["choices"][0]["taken"] = 4000; }, "choices[0].taken: clip 4000 is not in"},
    };
    // clang-format on
    for (const auto& [edit, place] : cases) {
        SCOPED_TRACE(place);
        write_edited(record, bad, edit);
        expect_refused(test::run_mobb("render --crowd " + bad + " --width 64 --height 64 --out " + png), bad, place,
                       png);
    }
    std::remove(bad.c_str());
}
#endif

}  // namespace
}  // namespace mobb
