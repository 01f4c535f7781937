// Malformed scene files: every numeric field and every clip index of a scene holding every key, broken in
// turn (zero, negative, non-finite, fractional, out of range, text), is refused with one line naming the
// file and the field, never accepted or crashed on.
#include <cstdio>
#include <fstream>
#include <functional>
#include <limits>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "scene.h"
#include "state.h"
#include "viewer_error.h"

namespace mobb::test {
namespace {

using nlohmann::json;

/// A scene with every key a scene file may hold, each within its range.
const json& full_scene() {
    static const json j = json::parse(R"({
      "clips": [
        {"file": "cmu/007_01.bvh", "up": "y", "scale": 0.056, "frames": "0:200", "fps": 60,
         "place": [-2.0, 0.0, 90.0, 0.6], "visible": true},
        {"random_walk": {"seconds": 6, "hz": 30, "seed": 3}, "place": [1.0, 0.0, 0.0, 0.5]}
      ],
      "generate": {"random_walks": 4, "seconds": 10, "hz": 60, "seed": 1, "spacing": 8},
      "tree": {"type": "mobb", "n_min": 10, "fit": "chord"},
      "query": {"a": 0, "b": 1, "step": 3},
      "layers": {"boxes": true, "level": 1, "levels": 2, "disk_colour": "speed"},
      "time": {"scale": 0.5, "cursor": 2.0, "window": 1.0},
      "skeleton_scale": 0.8,
      "camera": {"target": [0, 0, 3], "yaw": 35, "pitch": 25, "distance": 20, "fov": 45},
      "image": {"width": 320, "height": 240, "multisample": true}
    })");
    return j;
}

/// The error parse_scene gives the full scene after `edit`, "" when it reads.
std::string error_after(const std::function<void(json&)>& edit) {
    json j = full_scene();
    edit(j);
    try {
        viewer::parse_scene(j, "s.json");
    } catch (const viewer::ViewerError& e) {
        return e.what();
    }
    return "";
}

struct Case {
    const char* name;
    std::function<void(json&)> edit;
    const char* place;  // the error starts "s.json" + place + ": "
};

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

std::vector<Case> corpus() {
    // One case a line: clang-format 14 breaks up a short lambda that holds a braced list.
    // clang-format off
    return {
        // A clip file's loader options and placement.
        {"scale zero", [](json& j) { j["clips"][0]["scale"] = 0; }, ".clips[0].scale"},
        {"scale negative", [](json& j) { j["clips"][0]["scale"] = -0.01; }, ".clips[0].scale"},
        {"scale NaN", [](json& j) { j["clips"][0]["scale"] = kNaN; }, ".clips[0].scale"},
        {"scale huge", [](json& j) { j["clips"][0]["scale"] = 1e300; }, ".clips[0].scale"},
        {"scale tiny", [](json& j) { j["clips"][0]["scale"] = 1e-12; }, ".clips[0].scale"},
        {"scale text", [](json& j) { j["clips"][0]["scale"] = "cm"; }, ".clips[0].scale"},
        {"fps zero", [](json& j) { j["clips"][0]["fps"] = 0; }, ".clips[0].fps"},
        {"fps negative", [](json& j) { j["clips"][0]["fps"] = -30; }, ".clips[0].fps"},
        {"fps huge", [](json& j) { j["clips"][0]["fps"] = 1e9; }, ".clips[0].fps"},
        {"fps infinite", [](json& j) { j["clips"][0]["fps"] = kInf; }, ".clips[0].fps"},
        {"fps text", [](json& j) { j["clips"][0]["fps"] = "60"; }, ".clips[0].fps"},
        {"frames reversed", [](json& j) { j["clips"][0]["frames"] = "9:3"; }, ".clips[0].frames"},
        {"frames negative", [](json& j) { j["clips"][0]["frames"] = "-5:3"; }, ".clips[0].frames"},
        {"frames a number", [](json& j) { j["clips"][0]["frames"] = 5; }, ".clips[0].frames"},
        {"x far", [](json& j) { j["clips"][0]["place"][0] = 1e300; }, ".clips[0].place[0]"},
        {"x NaN", [](json& j) { j["clips"][0]["place"][0] = kNaN; }, ".clips[0].place[0]"},
        {"y far", [](json& j) { j["clips"][0]["place"][1] = -2e4; }, ".clips[0].place[1]"},
        {"y text", [](json& j) { j["clips"][0]["place"][1] = "0"; }, ".clips[0].place[1]"},
        {"theta infinite", [](json& j) { j["clips"][0]["place"][2] = kInf; }, ".clips[0].place[2]"},
        {"theta huge", [](json& j) { j["clips"][0]["place"][2] = 1e9; }, ".clips[0].place[2]"},
        {"t0 far", [](json& j) { j["clips"][1]["place"][3] = 1e5; }, ".clips[1].place[3]"},
        {"place of three", [](json& j) { j["clips"][0]["place"] = {1, 2, 3}; }, ".clips[0].place"},
        {"place a number", [](json& j) { j["clips"][0]["place"] = 1; }, ".clips[0].place"},
        // A clip's random walk.
        {"walk seconds zero", [](json& j) { j["clips"][1]["random_walk"]["seconds"] = 0; }, ".clips[1].random_walk.seconds"},
        {"walk seconds negative", [](json& j) { j["clips"][1]["random_walk"]["seconds"] = -6; }, ".clips[1].random_walk.seconds"},
        {"walk seconds NaN", [](json& j) { j["clips"][1]["random_walk"]["seconds"] = kNaN; }, ".clips[1].random_walk.seconds"},
        {"walk of no sample", [](json& j) { j["clips"][1]["random_walk"]["seconds"] = 0.001; }, ".clips[1].random_walk.seconds"},
        {"walk too long", [](json& j) { j["clips"][1]["random_walk"]["seconds"] = 1e9; }, ".clips[1].random_walk.seconds"},
        {"walk hz zero", [](json& j) { j["clips"][1]["random_walk"]["hz"] = 0; }, ".clips[1].random_walk.hz"},
        {"walk hz negative", [](json& j) { j["clips"][1]["random_walk"]["hz"] = -30; }, ".clips[1].random_walk.hz"},
        {"walk hz huge", [](json& j) { j["clips"][1]["random_walk"]["hz"] = 1e6; }, ".clips[1].random_walk.hz"},
        {"walk hz tiny", [](json& j) { j["clips"][1]["random_walk"]["hz"] = 1e-300; }, ".clips[1].random_walk.hz"},
        {"walk seed negative", [](json& j) { j["clips"][1]["random_walk"]["seed"] = -1; }, ".clips[1].random_walk.seed"},
        {"walk seed fractional", [](json& j) { j["clips"][1]["random_walk"]["seed"] = 1.5; }, ".clips[1].random_walk.seed"},
        {"walk seed past int", [](json& j) { j["clips"][1]["random_walk"]["seed"] = 4294967296LL; }, ".clips[1].random_walk.seed"},
        // Generated walks.
        {"walks negative", [](json& j) { j["generate"]["random_walks"] = -1; }, ".generate.random_walks"},
        {"walks too many", [](json& j) { j["generate"]["random_walks"] = 100000; }, ".generate.random_walks"},
        {"walks fractional", [](json& j) { j["generate"]["random_walks"] = 2.5; }, ".generate.random_walks"},
        {"generate seconds zero", [](json& j) { j["generate"]["seconds"] = 0; }, ".generate.seconds"},
        {"generate hz infinite", [](json& j) { j["generate"]["hz"] = kInf; }, ".generate.hz"},
        {"generate seed text", [](json& j) { j["generate"]["seed"] = "1"; }, ".generate.seed"},
        {"spacing zero", [](json& j) { j["generate"]["spacing"] = 0; }, ".generate.spacing"},
        {"spacing negative", [](json& j) { j["generate"]["spacing"] = -8; }, ".generate.spacing"},
        {"spacing far", [](json& j) { j["generate"]["spacing"] = 2e4; }, ".generate.spacing"},
        {"walks' samples together",
         [](json& j) { j["generate"] = {{"random_walks", 10000}, {"seconds", 600}, {"hz", 60}}; }, ".generate"},
        // Tree.
        {"n_min zero", [](json& j) { j["tree"]["n_min"] = 0; }, ".tree.n_min"},
        {"n_min negative", [](json& j) { j["tree"]["n_min"] = -5; }, ".tree.n_min"},
        {"n_min fractional", [](json& j) { j["tree"]["n_min"] = 1.5; }, ".tree.n_min"},
        {"n_min huge", [](json& j) { j["tree"]["n_min"] = 1 << 22; }, ".tree.n_min"},
        // The query's clips (2 clips + 4 generated: 0..5) and its step.
        {"a past the clips", [](json& j) { j["query"]["a"] = 6; }, ".query.a"},
        {"b past the clips", [](json& j) { j["query"]["b"] = 99; }, ".query.b"},
        {"a below -1", [](json& j) { j["query"]["a"] = -2; }, ".query.a"},
        {"a fractional", [](json& j) { j["query"]["a"] = 0.5; }, ".query.a"},
        {"b huge", [](json& j) { j["query"]["b"] = 1e12; }, ".query.b"},
        {"a and b the same", [](json& j) { j["query"]["b"] = 0; }, ".query.b"},
        {"a alone none", [](json& j) { j["query"]["a"] = -1; }, ".query.a"},
        {"b alone none", [](json& j) { j["query"]["b"] = -1; }, ".query.b"},
        {"step below -1", [](json& j) { j["query"]["step"] = -2; }, ".query.step"},
        {"step fractional", [](json& j) { j["query"]["step"] = 1.5; }, ".query.step"},
        {"step text", [](json& j) { j["query"]["step"] = "3"; }, ".query.step"},
        // Layers.
        {"level negative", [](json& j) { j["layers"]["level"] = -1; }, ".layers.level"},
        {"level past 63", [](json& j) { j["layers"]["level"] = 64; }, ".layers.level"},
        {"levels zero", [](json& j) { j["layers"]["levels"] = 0; }, ".layers.levels"},
        {"levels NaN", [](json& j) { j["layers"]["levels"] = kNaN; }, ".layers.levels"},
        // Time.
        {"time scale zero", [](json& j) { j["time"]["scale"] = 0; }, ".time.scale"},
        {"time scale negative", [](json& j) { j["time"]["scale"] = -1; }, ".time.scale"},
        {"time scale huge", [](json& j) { j["time"]["scale"] = 1e9; }, ".time.scale"},
        {"time scale tiny", [](json& j) { j["time"]["scale"] = 1e-300; }, ".time.scale"},
        {"time scale NaN", [](json& j) { j["time"]["scale"] = kNaN; }, ".time.scale"},
        {"cursor far", [](json& j) { j["time"]["cursor"] = 1e300; }, ".time.cursor"},
        {"cursor infinite", [](json& j) { j["time"]["cursor"] = -kInf; }, ".time.cursor"},
        {"cursor text", [](json& j) { j["time"]["cursor"] = "2"; }, ".time.cursor"},
        {"window negative", [](json& j) { j["time"]["window"] = -1; }, ".time.window"},
        {"window huge", [](json& j) { j["time"]["window"] = 1e9; }, ".time.window"},
        {"skeleton zero", [](json& j) { j["skeleton_scale"] = 0; }, ".skeleton_scale"},
        {"skeleton negative", [](json& j) { j["skeleton_scale"] = -0.8; }, ".skeleton_scale"},
        {"skeleton of a giant", [](json& j) { j["skeleton_scale"] = 100; }, ".skeleton_scale"},
        {"skeleton NaN", [](json& j) { j["skeleton_scale"] = kNaN; }, ".skeleton_scale"},
        // Camera.
        {"target x far", [](json& j) { j["camera"]["target"][0] = 1e300; }, ".camera.target[0]"},
        {"target t NaN", [](json& j) { j["camera"]["target"][2] = kNaN; }, ".camera.target[2]"},
        {"target of two", [](json& j) { j["camera"]["target"] = {0, 0}; }, ".camera.target"},
        {"yaw huge", [](json& j) { j["camera"]["yaw"] = 1e300; }, ".camera.yaw"},
        {"yaw NaN", [](json& j) { j["camera"]["yaw"] = kNaN; }, ".camera.yaw"},
        {"pitch past the pole", [](json& j) { j["camera"]["pitch"] = 90; }, ".camera.pitch"},
        {"pitch below", [](json& j) { j["camera"]["pitch"] = -100; }, ".camera.pitch"},
        {"distance zero", [](json& j) { j["camera"]["distance"] = 0; }, ".camera.distance"},
        {"distance negative", [](json& j) { j["camera"]["distance"] = -20; }, ".camera.distance"},
        {"distance past float", [](json& j) { j["camera"]["distance"] = 1e300; }, ".camera.distance"},
        {"fov zero", [](json& j) { j["camera"]["fov"] = 0; }, ".camera.fov"},
        {"fov 170", [](json& j) { j["camera"]["fov"] = 200; }, ".camera.fov"},
        {"fov NaN", [](json& j) { j["camera"]["fov"] = kNaN; }, ".camera.fov"},
        // Image.
        {"width zero", [](json& j) { j["image"]["width"] = 0; }, ".image.width"},
        {"width too small", [](json& j) { j["image"]["width"] = 10; }, ".image.width"},
        {"width huge", [](json& j) { j["image"]["width"] = 100000; }, ".image.width"},
        {"width fractional", [](json& j) { j["image"]["width"] = 320.5; }, ".image.width"},
        {"height negative", [](json& j) { j["image"]["height"] = -240; }, ".image.height"},
    };
    // clang-format on
}

TEST(SceneErrors, FullSceneReads) {
    EXPECT_EQ(error_after([](json&) {}), "");
    // The ranges' ends are allowed.
    EXPECT_EQ(error_after([](json& j) {
                  j["time"]["scale"] = viewer::kMaxTimeScale;
                  j["clips"][0]["place"] = {-viewer::kFar, viewer::kFar, -viewer::kFar, viewer::kFar};
                  j["camera"]["pitch"] = 89.9;
                  j["query"] = {{"a", -1}, {"b", -1}, {"step", -1}};
              }),
              "");
}

TEST(SceneErrors, EveryBadFieldIsNamed) {
    for (const Case& c : corpus()) {
        SCOPED_TRACE(c.name);
        const std::string e = error_after(c.edit);
        ASSERT_FALSE(e.empty()) << "accepted";
        EXPECT_EQ(e.rfind(std::string("s.json") + c.place + ": ", 0), 0u) << e;
        EXPECT_EQ(e.find('\n'), std::string::npos) << e;
    }
}

// From a file: the file named first, one line, ViewerError.
TEST(SceneErrors, FilesNameTheFileAndTheField) {
    const std::string file = std::string(MOBB_TEST_OUT) + "/scene_zero_scale.json";
    json j = full_scene();
    j["time"]["scale"] = 0;
    std::ofstream(file) << j.dump();
    try {
        viewer::load_scene(file);
        FAIL() << "accepted";
    } catch (const viewer::ViewerError& e) {
        EXPECT_EQ(std::string(e.what()), file + ".time.scale: expected a number in 0.05..20, got 0");
    }
    std::remove(file.c_str());
}

// The smallest walk a scene accepts, one sample, builds its tree and runs its query.
TEST(SceneErrors, OneSampleWalkLoads) {
    json j = full_scene();
    j["clips"][0] = {{"random_walk", {{"seconds", 0.02}, {"hz", 50}}}};
    j.erase("generate");
    const viewer::State s = viewer::load_state(viewer::parse_scene(j, "s.json"), 1.0f);
    EXPECT_EQ(s.clips[0].tree->path().samples.size(), 1u);
    EXPECT_TRUE(s.queried);
}

}  // namespace
}  // namespace mobb::test
