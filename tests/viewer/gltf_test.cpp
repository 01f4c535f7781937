// export-gltf: the file loads back with the expected meshes and nodes.
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include "export_gltf.h"
#include "render_test_util.h"
#include "scene.h"
#include "state.h"

namespace mobb::test {
namespace {

tinygltf::Model load(const std::string& file) {
    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    std::string err, warn;
    EXPECT_TRUE(loader.LoadBinaryFromFile(&model, &err, &warn, file)) << err;
    return model;
}

TEST(ExportGltf, SyntheticWalksWithBoxesAndTraceStep) {
    // walks.json: two clips with disks and boxes (level 1) visible, and trace step 3.
    const viewer::State s = viewer::load_state(viewer::load_scene(test_scene("walks.json")), 4.0f / 3.0f);
    const std::string file = std::string(MOBB_TEST_OUT) + "/walks.glb";
    std::filesystem::create_directories(MOBB_TEST_OUT);
    const viewer::GltfSummary summary = viewer::export_gltf(s, file);
    const tinygltf::Model m = load(file);
    EXPECT_EQ(m.meshes.size(), 5u);  // 2 disk stacks, 2 box sets, 1 trace step
    EXPECT_EQ(m.nodes.size(), 5u);
    EXPECT_EQ(int(m.meshes.size()), summary.meshes);
    EXPECT_EQ(m.scenes.at(0).nodes.size(), 5u);
    // Time runs up: the disks reach t * scale = 6.5 s * 0.5 m/s on y.
    const auto& pos = m.accessors.at(std::size_t(m.meshes[0].primitives[0].attributes.at("POSITION")));
    ASSERT_EQ(pos.maxValues.size(), 3u);
    EXPECT_NEAR(pos.maxValues[1], 6.0 * 0.5, 0.05);
    EXPECT_EQ(m.meshes[0].primitives[0].mode, TINYGLTF_MODE_TRIANGLES);
}

TEST(ExportGltf, RealClipsDisksOnly) {
    MOBB_NEEDS_MOCAP();
    const viewer::State s = viewer::load_state(viewer::load_scene(test_scene("pair.json")), 4.0f / 3.0f);
    const std::string file = std::string(MOBB_TEST_OUT) + "/pair.glb";
    std::filesystem::create_directories(MOBB_TEST_OUT);
    viewer::export_gltf(s, file);
    const tinygltf::Model m = load(file);
    EXPECT_EQ(m.meshes.size(), 2u);
    EXPECT_EQ(m.nodes.size(), 2u);
    EXPECT_EQ(m.materials.size(), 2u);
}

}  // namespace
}  // namespace mobb::test
