// Scene files: defaults, round trip, and one clear error naming the file and the key.
#include <fstream>

#include <gtest/gtest.h>

#include "render_test_util.h"
#include "scene.h"
#include "state.h"
#include "viewer_error.h"

namespace mobb::test {
namespace {

std::string error_of(const std::string& file) {
    try {
        viewer::load_scene(file);
    } catch (const viewer::ViewerError& e) {
        return e.what();
    }
    return "";
}

std::string error_of_json(const std::string& text) {
    try {
        viewer::parse_scene(nlohmann::json::parse(text), "s.json");
    } catch (const viewer::ViewerError& e) {
        return e.what();
    }
    return "";
}

TEST(Scene, Errors) {
    EXPECT_EQ(error_of("/no/such/scene.json"), "/no/such/scene.json: cannot open scene file");
    const std::string malformed = error_of(test_scene("bad/malformed.json"));
    EXPECT_NE(malformed.find("malformed.json: "), std::string::npos) << malformed;
    EXPECT_NE(malformed.find("line 3"), std::string::npos) << malformed;
    EXPECT_EQ(error_of(test_scene("bad/wrong_type.json")),
              test_scene("bad/wrong_type.json") + ".layers.level: expected a whole number in 0..63");
    EXPECT_EQ(error_of_json(R"({"layres": {}})"), "s.json.layres: unknown key");
    EXPECT_EQ(error_of_json(R"({"clips": [{"file": 3}]})"), "s.json.clips[0].file: expected a string");
    EXPECT_EQ(error_of_json(R"({"clips": [{"file": "a.bvh", "place": [1, 2]}]})"),
              "s.json.clips[0].place: expected an array of 4 numbers");
    EXPECT_EQ(error_of_json(R"({"clips": [{}]})"),
              "s.json.clips[0]: expected exactly one of \"file\" and \"random_walk\"");
    EXPECT_EQ(error_of_json(R"({"clips": [{"file": "a.bvh"}, {"file": "b.bvh"}], "query": {"a": 0, "b": 5}})"),
              "s.json.query.b: clip 5 past the scene's 2 clips (-1 for none)");
    EXPECT_EQ(error_of_json(R"({"time": {"window": -1}})"),
              "s.json.time.window: expected a number in 0..10000, got -1");
    EXPECT_EQ(error_of_json(R"({"tree": {"type": "octree"}})"),
              "s.json.tree.type: expected one of mobb, umobb, hybrid1, hybrid2, mobb1, umobb1");
    EXPECT_NE(
        error_of_json(R"({"clips": [{"file": "a.bvh", "frames": "9:3"}]})").find("s.json.clips[0].frames: --frames"),
        std::string::npos);
}

TEST(Scene, MissingClipFileNamesTheFile) {
    const viewer::Scene scene = viewer::load_scene(test_scene("bad/missing_clip.json"));
    try {
        viewer::load_state(scene, 1.0f);
        FAIL() << "expected an error";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("no_such_clip.bvh"), std::string::npos) << e.what();
    }
}

TEST(Scene, RoundTrip) {
    viewer::Scene a = viewer::load_scene(test_scene("walks.json"));
    a.layers.level = 3;
    a.cursor = 1.25;
    a.window = 0.75;
    a.multisample = false;
    const std::string file = std::string(MOBB_TEST_OUT) + "/round_trip.json";
    std::filesystem::create_directories(MOBB_TEST_OUT);
    viewer::save_scene(a, file);
    const viewer::Scene b = viewer::load_scene(file);
    EXPECT_EQ(viewer::scene_json(a).dump(), viewer::scene_json(b).dump());
    EXPECT_EQ(b.layers.level, 3);
    EXPECT_EQ(b.window, 0.75);
    EXPECT_FALSE(b.multisample);
    EXPECT_TRUE(viewer::load_scene(test_scene("walks.json")).multisample);  // on unless a scene says off
    EXPECT_EQ(b.clips.size(), 2u);
    EXPECT_NEAR(b.clips[1].place.t0, 0.5, 1e-12);
}

TEST(Scene, EveryAssetSceneParses) {
    for (const auto& entry :
         std::filesystem::directory_iterator(std::string(MOBB_TEST_SCENES) + "/../../../assets/scenes")) {
        if (entry.path().extension() != ".json") continue;
        EXPECT_NO_THROW(viewer::load_scene(entry.path().string())) << entry.path();
    }
}

TEST(State, QueryTraceAndStepClamp) {
    viewer::State s = viewer::load_state(viewer::load_scene(test_scene("walks.json")), 1.0f);
    ASSERT_TRUE(s.queried);
    ASSERT_FALSE(s.trace.empty());
    s.scene.step = 1 << 20;
    EXPECT_EQ(viewer::shown_step(s), int(s.trace.size()) - 1);
    const std::uint64_t before = s.revision;
    s.places[1].x += 0.5;
    viewer::run_query(s);
    EXPECT_GT(s.revision, before);
}

}  // namespace
}  // namespace mobb::test
