// Malformed motion graphs: every numeric field of the committed graph broken in turn (zero, negative,
// non-finite, fractional, out of range, inconsistent with the rest) is refused with one line naming the
// field, never accepted or crashed on.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <limits>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "files.h"
#include "mobb/crowd/graph/motion_graph.h"

namespace mobb::crowd {
namespace {

using nlohmann::json;

const std::string kGraph = std::string(MOBB_SOURCE_DIR) + "/assets/graphs/cmu_locomotion.json";

const json& committed() {
    static const json j = [] {
        std::ifstream in(kGraph);
        return json::parse(in);
    }();
    return j;
}

// The error graph_from_json gives the committed graph after `edit`, "" when it reads.
std::string error_after(const std::function<void(json&)>& edit) {
    json j = committed();
    edit(j);
    try {
        graph_from_json(j, "g.json: graph");
    } catch (const GraphError& e) {
        return e.what();
    }
    return "";
}

struct Case {
    const char* name;
    std::function<void(json&)> edit;
    const char* place;  // the error starts "g.json: graph" + place + ": "
};

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

// Clip 75 of the committed graph is its idle clip (exit snapped to the identity, "idle_snap" given);
// clip 0 walks, from source 3 (no frame_end); clip 80 comes from a source with a frame_end.
std::vector<Case> corpus() {
    // One case a line: clang-format 14 breaks up a short lambda that holds a braced list.
    // clang-format off
    return {
        // Rate, threshold, window.
        {"fps zero", [](json& j) { j["fps"] = 0; }, ".fps"},
        {"fps negative", [](json& j) { j["fps"] = -30; }, ".fps"},
        {"fps NaN", [](json& j) { j["fps"] = kNaN; }, ".fps"},
        {"fps infinite", [](json& j) { j["fps"] = kInf; }, ".fps"},
        {"fps text", [](json& j) { j["fps"] = "30"; }, ".fps"},
        {"fps too small for a finite dt", [](json& j) { j["fps"] = 1e-320; }, ".fps"},
        {"fps below mocap", [](json& j) { j["fps"] = 0.5; }, ".fps"},
        {"fps above mocap", [](json& j) { j["fps"] = 1e9; }, ".fps"},
        {"dt zero", [](json& j) { j["dt"] = 0; }, ".dt"},
        {"dt negative", [](json& j) { j["dt"] = -1.0 / 30; }, ".dt"},
        {"dt not 1 / fps", [](json& j) { j["dt"] = 0.04; }, ".dt"},
        {"dt NaN", [](json& j) { j["dt"] = kNaN; }, ".dt"},
        {"threshold zero", [](json& j) { j["threshold"] = 0; }, ".threshold"},
        {"threshold negative", [](json& j) { j["threshold"] = -0.12; }, ".threshold"},
        {"threshold infinite", [](json& j) { j["threshold"] = kInf; }, ".threshold"},
        {"window zero", [](json& j) { j["window"] = 0; }, ".window"},
        {"window negative", [](json& j) { j["window"] = -5; }, ".window"},
        {"window fractional", [](json& j) { j["window"] = 2.5; }, ".window"},
        {"window huge", [](json& j) { j["window"] = 1e300; }, ".window"},
        {"window past int", [](json& j) { j["window"] = 4294967296LL; }, ".window"},
        {"version", [](json& j) { j["version"] = 7; }, ".version"},
        {"format", [](json& j) { j["format"] = "mobb crowd record"; }, ".format"},
        {"joint name", [](json& j) { j["joints"][0] = 3; }, ".joints[0]"},
        // Sources.
        {"no sources", [](json& j) { j["sources"] = json::array(); }, ".clips[0].source"},
        {"sources an object", [](json& j) { j["sources"] = json::object(); }, ".sources"},
        {"frame_begin negative", [](json& j) { j["sources"][0]["frame_begin"] = -1; }, ".sources[0].frame_begin"},
        {"frame_begin fractional", [](json& j) { j["sources"][0]["frame_begin"] = 0.5; }, ".sources[0].frame_begin"},
        {"frame_end before begin", [](json& j) { j["sources"][5]["frame_end"] = 0; }, ".sources[5].frame_end"},
        {"frame_end below -1", [](json& j) { j["sources"][0]["frame_end"] = -2; }, ".sources[0].frame_end"},
        {"source samples zero", [](json& j) { j["sources"][0]["samples"] = 0; }, ".sources[0].samples"},
        {"source samples negative", [](json& j) { j["sources"][0]["samples"] = -86; }, ".sources[0].samples"},
        {"source file a number", [](json& j) { j["sources"][0]["file"] = 7; }, ".sources[0].file"},
        // A clip's identity and ranges.
        {"id not its index", [](json& j) { j["clips"][3]["id"] = 4; }, ".clips[3].id"},
        {"source negative", [](json& j) { j["clips"][0]["source"] = -1; }, ".clips[0].source"},
        {"source past the sources", [](json& j) { j["clips"][0]["source"] = 999; }, ".clips[0].source"},
        {"zero samples", [](json& j) { j["clips"][0]["samples"] = {5, 5}; }, ".clips[0].samples"},
        {"samples reversed", [](json& j) { j["clips"][0]["samples"] = {39, 0}; }, ".clips[0].samples"},
        {"samples negative", [](json& j) { j["clips"][0]["samples"] = {-1, 38}; }, ".clips[0].samples"},
        {"exit past the source", [](json& j) { j["clips"][0]["samples"] = {0, 100000}; }, ".clips[0].samples"},
        {"samples fractional", [](json& j) { j["clips"][0]["samples"] = {0, 38.5}; }, ".clips[0].samples[1]"},
        {"frames reversed", [](json& j) { j["clips"][0]["frames"] = {78, 0}; }, ".clips[0].frames"},
        {"frames before the source", [](json& j) { j["clips"][0]["frames"] = {-2, 78}; }, ".clips[0].frames"},
        {"frames past frame_end",
         [](json& j) {
             for (auto& c : j["clips"])
                 if (j["sources"][c["source"].get<std::size_t>()]["frame_end"] == 319) c["frames"] = {0, 400};
         },
         ".clips["},
        {"duration wrong", [](json& j) { j["clips"][0]["duration"] = 99; }, ".clips[0].duration"},
        {"duration negative", [](json& j) { j["clips"][0]["duration"] = -1.3; }, ".clips[0].duration"},
        {"kind unknown", [](json& j) { j["clips"][0]["kind"] = "run"; }, ".clips[0].kind"},
        // Exit and idle snap.
        {"exit x text", [](json& j) { j["clips"][0]["exit"][0] = "far"; }, ".clips[0].exit[0]"},
        {"exit y NaN", [](json& j) { j["clips"][0]["exit"][1] = kNaN; }, ".clips[0].exit[1]"},
        {"exit heading past pi", [](json& j) { j["clips"][0]["exit"][2] = 4.0; }, ".clips[0].exit[2]"},
        {"exit heading infinite", [](json& j) { j["clips"][0]["exit"][2] = -kInf; }, ".clips[0].exit[2]"},
        {"exit two numbers", [](json& j) { j["clips"][0]["exit"] = {1, 2}; }, ".clips[0].exit"},
        {"exit far", [](json& j) { j["clips"][0]["exit"][0] = 1e5; }, ".clips[0].exit[0]"},
        {"idle_snap on a walk", [](json& j) { j["clips"][0]["idle_snap"] = {0.01, 0.0}; }, ".clips[0].idle_snap"},
        {"idle drift negative", [](json& j) { j["clips"][75]["idle_snap"][0] = -0.01; }, ".clips[75].idle_snap[0]"},
        {"idle drift too far", [](json& j) { j["clips"][75]["idle_snap"][0] = 0.5; }, ".clips[75].idle_snap[0]"},
        {"idle turn too far", [](json& j) { j["clips"][75]["idle_snap"][1] = 1.0; }, ".clips[75].idle_snap[1]"},
        {"idle_snap text", [](json& j) { j["clips"][75]["idle_snap"] = "small"; }, ".clips[75].idle_snap"},
        // Edges.
        {"no successors", [](json& j) { j["clips"][0]["successors"] = json::array(); }, ".clips[0].successors"},
        {"successor past the clips",
         [](json& j) {
             j["clips"][0]["successors"][1] = 81;  // 81 clips: 0..80
         },
         ".clips[0].successors[1]"},
        {"successor negative", [](json& j) { j["clips"][2]["successors"][0] = -1; }, ".clips[2].successors[0]"},
        {"successor twice", [](json& j) { j["clips"][0]["successors"][1] = j["clips"][0]["successors"][0]; },
         ".clips[0].successors[1]"},
        {"successor fractional", [](json& j) { j["clips"][0]["successors"][0] = 1.5; }, ".clips[0].successors[0]"},
        {"distances short", [](json& j) { j["clips"][0]["distances"].erase(0); }, ".clips[0].distances"},
        {"distance negative", [](json& j) { j["clips"][0]["distances"][0] = -0.01; }, ".clips[0].distances[0]"},
        {"distance over the threshold", [](json& j) { j["clips"][0]["distances"][0] = 0.5; },
         ".clips[0].distances[0]"},
        {"distance NaN", [](json& j) { j["clips"][0]["distances"][3] = kNaN; }, ".clips[0].distances[3]"},
        // Paths.
        {"radius negative", [](json& j) { j["clips"][0]["path"][3][2] = -0.1; }, ".clips[0].path[3][2]"},
        {"radius NaN", [](json& j) { j["clips"][0]["path"][3][2] = kNaN; }, ".clips[0].path[3][2]"},
        {"radius infinite", [](json& j) { j["clips"][0]["path"][3][2] = kInf; }, ".clips[0].path[3][2]"},
        {"x infinite", [](json& j) { j["clips"][0]["path"][4][0] = kInf; }, ".clips[0].path[4][0]"},
        {"x far", [](json& j) { j["clips"][0]["path"][4][0] = 1e300; }, ".clips[0].path[4][0]"},
        {"y far", [](json& j) { j["clips"][0]["path"][4][1] = -5000.0; }, ".clips[0].path[4][1]"},
        {"radius of a giant", [](json& j) { j["clips"][0]["path"][3][2] = 50.0; }, ".clips[0].path[3][2]"},
        {"y NaN", [](json& j) { j["clips"][0]["path"][4][1] = kNaN; }, ".clips[0].path[4][1]"},
        {"x text", [](json& j) { j["clips"][0]["path"][4][0] = "0"; }, ".clips[0].path[4][0]"},
        {"sample of two numbers", [](json& j) { j["clips"][0]["path"][4] = {0, 0}; }, ".clips[0].path[4]"},
        {"path shorter than its samples", [](json& j) { j["clips"][0]["path"].erase(5); }, ".clips[0].path"},
        {"path empty", [](json& j) { j["clips"][0]["path"] = json::array(); }, ".clips[0].path"},
        {"first sample off the origin", [](json& j) { j["clips"][0]["path"][0][0] = 1.0; }, ".clips[0].path[0]"},
        // Statistics: what the clips add up to.
        {"stats clips", [](json& j) { j["stats"]["clips"] = 80; }, ".stats.clips"},
        {"stats clips negative", [](json& j) { j["stats"]["clips"] = -81; }, ".stats.clips"},
        {"stats edges", [](json& j) { j["stats"]["edges"] = 1; }, ".stats.edges"},
        {"stats mean duration", [](json& j) { j["stats"]["mean_duration"] = 0; }, ".stats.mean_duration"},
        {"stats min duration", [](json& j) { j["stats"]["min_duration"] = -0.8; }, ".stats.min_duration"},
        {"stats max duration", [](json& j) { j["stats"]["max_duration"] = kNaN; }, ".stats.max_duration"},
        {"stats mean successors", [](json& j) { j["stats"]["mean_successors"] = 2; }, ".stats.mean_successors"},
        {"stats transition points", [](json& j) { j["stats"]["transition_points"] = -1; },
         ".stats.transition_points"},
        {"stats clips cut", [](json& j) { j["stats"]["clips_cut"] = 3; }, ".stats.clips_cut"},
        {"stats text", [](json& j) { j["stats"] = "many"; }, ".stats"},
    };
    // clang-format on
}

TEST(GraphErrors, CommittedGraphReadsAndKeepsItsStatistics) {
    EXPECT_EQ(error_after([](json&) {}), "");
    const MotionGraph g = graph_from_json(committed(), "g");
    EXPECT_EQ(g.transitions, committed()["stats"]["transition_points"].get<int>());
    EXPECT_EQ(g.clips_cut, committed()["stats"]["clips_cut"].get<int>());
    EXPECT_EQ(g.clips[75].idle_drift, committed()["clips"][75]["idle_snap"][0].get<double>());
    // What a graph may leave out: dt, stats, distances, durations, ids, kinds, idle snaps of idle clips.
    EXPECT_EQ(error_after([](json& j) {
                  j.erase("dt");
                  j.erase("stats");
                  for (auto& c : j["clips"])
                      for (const char* key : {"distances", "duration", "id", "kind", "idle_snap"}) c.erase(key);
              }),
              "");
}

TEST(GraphErrors, EveryBadFieldIsNamed) {
    for (const Case& c : corpus()) {
        SCOPED_TRACE(c.name);
        const std::string e = error_after(c.edit);
        ASSERT_FALSE(e.empty()) << "accepted";
        EXPECT_EQ(e.rfind(std::string("g.json: graph") + c.place, 0), 0u) << e;
        EXPECT_NE(e.find(": ", std::string("g.json: graph").size()), std::string::npos) << e;
        EXPECT_EQ(e.find('\n'), std::string::npos) << e;
    }
}

// A graph whose disks are centred on the body: each clip gives its root at every sample, the first at the
// origin, each inside its disk.
TEST(GraphErrors, EnclosingGraphFieldsAreNamed) {
    std::ifstream in(std::string(MOBB_SOURCE_DIR) + "/assets/graphs/cmu_locomotion_enclosing.json");
    const json body = json::parse(in);
    auto error = [&](const std::function<void(json&)>& edit) {
        json j = body;
        edit(j);
        try {
            graph_from_json(j, "g.json: graph");
        } catch (const GraphError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_EQ(error([](json&) {}), "");
    EXPECT_EQ(error([](json& j) { j["clips"][3].erase("root"); }).rfind("g.json: graph.clips[3]: ", 0), 0u);
    EXPECT_EQ(error([](json& j) { j["clips"][3]["root"].erase(0); }).rfind("g.json: graph.clips[3].root: ", 0), 0u);
    EXPECT_EQ(error([](json& j) { j["clips"][3]["root"][2] = {0.1}; }).rfind("g.json: graph.clips[3].root[2]: ", 0),
              0u);
    EXPECT_EQ(error([](json& j) { j["clips"][3]["root"][0][0] = 0.01; }).rfind("g.json: graph.clips[3].root[0]: ", 0),
              0u);
    const std::string outside = error([](json& j) { j["clips"][3]["root"][5] = {3.0, 0.0}; });
    EXPECT_EQ(outside.rfind("g.json: graph.clips[3].root[5]: ", 0), 0u) << outside;
    EXPECT_NE(outside.find("outside its sample's disk"), std::string::npos) << outside;
    EXPECT_EQ(error([](json& j) { j["clips"][3]["path"][0][0] = 2.0; }).rfind("g.json: graph.clips[3].root[0]: ", 0),
              0u);
    EXPECT_EQ(error([](json& j) { j["centre"] = "middle"; }).rfind("g.json: graph.centre: ", 0), 0u);
    // Without "centre" its disks off the root are refused as the root's.
    EXPECT_EQ(error([](json& j) { j.erase("centre"); }).rfind("g.json: graph.clips[0].path[0]: ", 0), 0u);
}

// From a file: the file named first, one line, GraphError.
TEST(GraphErrors, FilesNameTheFileAndTheField) {
    const std::string file = test::temp_file("graph_zero_dt.json");
    json j = committed();
    j["dt"] = 0;
    std::ofstream(file) << j.dump();
    try {
        load_graph(file);
        FAIL() << "accepted";
    } catch (const GraphError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(file + ": graph.dt: ", 0), 0u) << e.what();
    }
    std::ofstream(file) << R"({"fps": 30, "threshold": 0.1, "window": 5, "sources": [{"file": "a.bvh",
        "frame_begin": 0, "samples": 10}], "clips": [{"source": 0, "samples": [2, 2], "frames": [2, 2],
        "exit": [0, 0, 0], "successors": [0], "path": [[0, 0, 0.3]]}]})";
    try {
        load_graph(file);
        FAIL() << "accepted";
    } catch (const GraphError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(file + ": graph.clips[0].samples: [2, 2]", 0), 0u) << e.what();
    }
    std::remove(file.c_str());
}

}  // namespace
}  // namespace mobb::crowd
