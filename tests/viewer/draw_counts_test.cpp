// What the renderer asks of the GL per frame, counted (draw_counts.h), not timed: the bench scene's
// 360,000 disks take a bounded number of draw calls (consecutive chunks of a stack at one level of
// detail are one call), they still draw every chunk in view at its own level of detail, and as tubes.
#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "context_osmesa.h"
#include "disk_lod.h"
#include "renderer.h"
#include "scene.h"
#include "state.h"
#include "target.h"

namespace mobb::test {
namespace {

/// Instances and runs (consecutive chunks at one k) a chunk-by-chunk drawing of the frame draws.
struct Expected {
    std::size_t instances = 0, runs = 0;
};

Expected chunk_by_chunk(const render::Frame& frame, const glm::mat4& view_proj, int height) {
    std::size_t total = 0;
    for (const auto& c : frame.clips) total += c.tree->path().size();
    Expected e;
    for (const auto& clip : frame.clips) {
        const Path& path = clip.tree->path();
        const std::vector<render::Bounds> chunks = render::chunk_bounds(path, clip.place);
        int last_k = 0;
        for (std::size_t q = 0; q < chunks.size(); ++q) {
            glm::vec3 lo, hi;
            render::gl_bounds(chunks[q], frame.time_scale, lo, hi);
            if (render::outside_view(view_proj, lo, hi)) {
                last_k = 0;
                continue;
            }
            const int k = render::clip_lod(chunks[q], path.dt, frame.time_scale, total, view_proj, height);
            const std::size_t n = std::min(path.size() - q * render::kDiskChunk, std::size_t(render::kDiskChunk));
            e.instances += (n + std::size_t(k) - 1) / std::size_t(k);
            e.runs += k != last_k;
            last_k = k;
        }
    }
    return e;
}

TEST(DrawCounts, BenchSceneInFewCalls) {
    const int w = 1280, h = 720;
    const viewer::Scene scene = viewer::load_scene(std::string(MOBB_ASSET_SCENES) + "/bench.json");
    const viewer::State s = viewer::load_state(scene, float(w) / float(h));
    const render::Frame frame = viewer::frame_of(s);
    render::OsMesaContext context(w, h);
    render::Target target(w, h);
    target.bind();
    render::Renderer renderer;
    renderer.draw(frame, s.camera, w, h);

    const glm::mat4 view_proj = s.camera.projection(float(w) / float(h)) * s.camera.view();
    const Expected e = chunk_by_chunk(frame, view_proj, h);
    ASSERT_EQ(frame.clips.size(), 100u);
    EXPECT_EQ(renderer.disk_stats().disks, 360000u);
    EXPECT_EQ(renderer.disk_stats().instances, e.instances);
    // One call per run of each stack, and a few for the grid, the boxes, the cursor and the labels:
    // drawn chunk by chunk, the stacks alone took one call per chunk in view (up to 8 per stack).
    const render::DrawCounts counts = renderer.draw_counts();
    EXPECT_GE(counts.calls, e.runs);
    EXPECT_LE(counts.calls, e.runs + 16);
    EXPECT_LE(e.runs, 2 * frame.clips.size());
    // Stacks seen whole, opaque, in their clips' colours are tubes: 8 segments, 16 triangles per group,
    // where grouped cylinders took 24 (72 indices); the other layers add a few thousand vertices.
    EXPECT_GE(counts.vertices, 48 * e.instances);
    EXPECT_LT(counts.vertices, 72 * e.instances);
}

TEST(DrawCounts, MultisampledUnlessOffOrACrowd) {
    viewer::State small = viewer::load_state(viewer::load_scene(std::string(MOBB_TEST_SCENES) + "/walks.json"), 1.0f);
    EXPECT_TRUE(render::multisampled(viewer::frame_of(small)));
    small.scene.multisample = false;  // View > Smooth edges, --no-msaa
    EXPECT_FALSE(render::multisampled(viewer::frame_of(small)));
    const viewer::State crowd =
        viewer::load_state(viewer::load_scene(std::string(MOBB_ASSET_SCENES) + "/bench.json"), 1.0f);
    EXPECT_FALSE(render::multisampled(viewer::frame_of(crowd)));  // 360,000 disks
}

}  // namespace
}  // namespace mobb::test
