// The disk stacks' level of detail (disk_lod.h): ordinary scenes always draw one cylinder per
// sample (so the goldens cannot change), the 360,000-disk bench scene at 1280x720 groups samples, and
// a group's sheared cylinder holds every disk of the group. Pure functions: no GL, no timing.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "disk_lod.h"
#include "render_test_util.h"
#include "scene.h"
#include "state.h"

namespace mobb::test {
namespace {

using viewer::State;

std::string asset_scene(const std::string& name) { return std::string(MOBB_ASSET_SCENES) + "/" + name; }

/// Every clip's k for a scene file drawn at width x height with the scene's own camera.
std::vector<int> lods_of(const std::string& file, int width, int height, std::size_t* disks = nullptr) {
    const viewer::Scene scene = viewer::load_scene(file);
    const float aspect = float(width) / float(height);
    const State s = viewer::load_state(scene, aspect);
    const render::Frame frame = viewer::frame_of(s);
    if (disks) {
        *disks = 0;
        for (const auto& c : frame.clips) *disks += c.tree->path().size();
    }
    return render::frame_lods(frame, s.camera.projection(aspect) * s.camera.view(), height);
}

TEST(DiskLod, Decision) {
    // Small scenes: always 1, however thin a sample is on screen.
    EXPECT_EQ(render::disk_lod(0.001, 7000), 1);
    EXPECT_EQ(render::disk_lod(0.001, render::kDiskLodAbove), 1);
    // Crowds: 1 while a sample is more than kDiskLodPixels / 2 tall, else the largest power of two
    // whose group is at most kDiskLodPixels tall.
    const double p = render::kDiskLodPixels;
    EXPECT_EQ(render::disk_lod(p, 360000), 1);
    EXPECT_EQ(render::disk_lod(0.51 * p, 360000), 1);
    EXPECT_EQ(render::disk_lod(0.3 * p, 360000), 2);
    EXPECT_EQ(render::disk_lod(p / 100, 360000), 64);
    EXPECT_EQ(render::disk_lod(1e-9, 360000), render::kDiskLodMaxK);
    EXPECT_EQ(render::disk_lod(std::nan(""), 360000), 1);
    for (double px = 1e-4; px < 4; px *= 1.37) {
        const int k = render::disk_lod(px, 360000);
        EXPECT_EQ(k & (k - 1), 0) << px;
        EXPECT_TRUE(k == 1 || k * px <= render::kDiskLodPixels) << px;
        EXPECT_TRUE(k == render::kDiskLodMaxK || 2 * k * px > render::kDiskLodPixels) << px;
    }
}

TEST(DiskLod, OneForTheDefaultAndGoldenScenes) {
    MOBB_NEEDS_MOCAP();
    for (int k : lods_of(asset_scene("default.json"), 960, 540)) EXPECT_EQ(k, 1);
    for (const char* name : {"pair.json", "long.json"})
        for (int k : lods_of(test_scene(name), 320, 240)) EXPECT_EQ(k, 1) << name;
}

TEST(DiskLod, OneForSyntheticGoldenScene) {
    for (int k : lods_of(test_scene("walks.json"), 320, 240)) EXPECT_EQ(k, 1);
}

TEST(DiskLod, GroupsTheBenchScene) {
    std::size_t disks = 0;
    const std::vector<int> lods = lods_of(asset_scene("bench.json"), 1280, 720, &disks);
    ASSERT_EQ(lods.size(), 100u);
    EXPECT_EQ(disks, 360000u);
    for (int k : lods) {
        EXPECT_GT(k, 1);
        EXPECT_EQ(k & (k - 1), 0);
    }
}

TEST(DiskLod, GroupsHoldTheirDisks) {
    // A wandering path with a varying radius, grouped at several k (including a partial last group).
    Path path;
    path.dt = 1.0 / 60.0;
    double x = 0, y = 0, heading = 0;
    for (int i = 0; i < 1000; ++i) {
        heading += 0.05 * std::sin(0.013 * i * i);
        x += 0.03 * std::cos(heading);
        y += 0.03 * std::sin(heading);
        path.samples.push_back({x, y, 0.3 + 0.1 * std::sin(0.1 * i)});
    }
    const Placement place{1.0, -2.0, 0.7, 0.5};
    const std::vector<render::DiskInstance> disks = render::disk_instances(path, place);
    for (int k : {1, 2, 8, 64, 256}) {
        const std::vector<render::DiskGroup> groups = render::group_disks(disks, k);
        ASSERT_EQ(groups.size(), (disks.size() + std::size_t(k) - 1) / std::size_t(k)) << k;
        std::size_t i = 0;
        for (std::size_t g = 0; g < groups.size(); ++g) {
            const render::DiskGroup& G = groups[g];
            const auto m = std::size_t(G.shift.w);
            EXPECT_EQ(G.base.z, disks[i].z);  // groups tile the samples' time slots
            if (g + 1 < groups.size()) {
                // Consecutive groups meet centre to centre: no gaps in the stack.
                EXPECT_NEAR(G.base.x + G.shift.x, groups[g + 1].base.x, 1e-5);
                EXPECT_NEAR(G.base.y + G.shift.y, groups[g + 1].base.y, 1e-5);
                // The top cap is marked hidden exactly when the next group of the same chunk holds it.
                const bool chunk_end = (g + 1) * std::size_t(k) % std::size_t(render::kDiskChunk) == 0;
                EXPECT_EQ(G.shift.z, !chunk_end && groups[g + 1].base.w >= G.base.w ? 1.0f : 0.0f) << k << " " << g;
            } else {
                EXPECT_EQ(G.shift.z, 0.0f);  // the stack's top is always closed
            }
            for (std::size_t u = 0; u < m; ++u) {
                const render::DiskInstance& d = disks[i + u];
                for (double s : {double(u), double(u + 1)}) {  // the slot's start and end
                    const double ax = G.base.x + G.shift.x * s / double(m), ay = G.base.y + G.shift.y * s / double(m);
                    EXPECT_LE(std::hypot(d.x - ax, d.y - ay) + d.w, double(G.base.w) + 1e-5) << k << " " << g;
                }
            }
            i += m;
        }
        EXPECT_EQ(i, disks.size());
    }
}

/// A stack's groups as one tube: its vertex and index counts follow the formula (a ring per group
/// boundary, two triangles per segment and group, two capped ends), each ring holds the disks of the
/// groups it joins (so every segment holds its group's sheared cylinder), and every triangle faces out.
TEST(DiskLod, TubeHoldsItsGroups) {
    Path path;
    path.dt = 1.0 / 30.0;
    double x = 0, y = 0, heading = 0;
    for (int i = 0; i < 700; ++i) {
        heading += 0.04 * std::sin(0.011 * i * i);
        x += 0.04 * std::cos(heading);
        y += 0.04 * std::sin(heading);
        path.samples.push_back({x, y, 0.3 + 0.1 * std::sin(0.07 * i)});
    }
    const std::vector<render::DiskInstance> disks = render::disk_instances(path, {2.0, 1.0, 0.3, 1.5});
    const int s = 8;
    for (int k : {2, 16, 64}) {
        const std::vector<render::DiskGroup> groups = render::group_disks(disks, k);
        const render::TubeMesh m = render::tube_mesh(groups, path.dt, s);
        const std::size_t n = groups.size();
        ASSERT_EQ(m.vertices.size(), (n + 1) * s + 2 * s) << k;
        ASSERT_EQ(m.indices.size(), 6 * s * n + 2 * 3 * (s - 2)) << k;
        EXPECT_EQ(m.first_index(0), 0u);
        EXPECT_EQ(m.end_index(n), m.indices.size());
        EXPECT_EQ(m.end_index(n - 1) - m.first_index(1), 6 * s * (n - 2));  // a middle range: sides only
        const auto axis = [&](std::size_t g, double u) {  // the centre of group g's cylinder, u in [0, 1]
            const render::DiskGroup& G = groups[g];
            return glm::dvec2(G.base.x + u * G.shift.x, G.base.y + u * G.shift.y);
        };
        for (std::size_t g = 0; g < n; ++g)
            for (int q = 0; q < s; ++q)
                for (const auto& [ring, u] : {std::pair{g, 0.0}, std::pair{g + 1, 1.0}}) {
                    const glm::vec3 v = m.vertices[ring * s + std::size_t(q)].pos;
                    EXPECT_NEAR(v.z, groups[g].base.z + u * path.dt * groups[g].shift.w, 1e-4);
                    const double d = glm::length(glm::dvec2(v.x, v.y) - axis(g, u));
                    EXPECT_GE(d, double(groups[g].base.w) - 1e-5) << k << " " << g;
                }
        for (std::size_t i = 0; i < m.indices.size(); i += 3) {
            const glm::dvec3 a(m.vertices[m.indices[i]].pos), b(m.vertices[m.indices[i + 1]].pos),
                c(m.vertices[m.indices[i + 2]].pos);
            const glm::dvec3 normal = glm::cross(b - a, c - a), mid = (a + b + c) / 3.0;
            if (i < m.cap_indices()) {
                EXPECT_LT(normal.z, 0.0);  // the bottom cap faces down in time
            } else if (i >= m.indices.size() - m.cap_indices()) {
                EXPECT_GT(normal.z, 0.0);
            } else {
                const std::size_t g = (i - m.cap_indices()) / (6 * s);
                const double u = (mid.z - groups[g].base.z) / (path.dt * groups[g].shift.w);
                EXPECT_GT(glm::dot(glm::dvec2(normal), glm::dvec2(mid) - axis(g, u)), 0.0) << k << " " << i;
            }
        }
    }
}

/// Chunks of kDiskChunk samples: each holds its samples' disks over its time slot, and together they
/// make the path's bounds.
TEST(DiskLod, ChunkBoundsHoldTheirDisks) {
    Path path;
    path.dt = 0.02;
    for (int i = 0; i < 2 * render::kDiskChunk + 37; ++i)
        path.samples.push_back({0.01 * i, std::sin(0.01 * i), 0.2 + 0.1 * std::cos(0.03 * i)});
    const Placement place{1.0, -2.0, 0.7, 3.0};
    const std::vector<render::Bounds> chunks = render::chunk_bounds(path, place);
    ASSERT_EQ(chunks.size(), 3u);
    const render::Bounds whole = render::path_bounds(path, place);
    render::Bounds joined;
    for (const auto& b : chunks) joined.add(b.lo), joined.add(b.hi);
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(joined.lo[k], whole.lo[k], 1e-12);
        EXPECT_NEAR(joined.hi[k], whole.hi[k], 1e-12);
    }
    const Rigid2 m = Rigid2::of(place);
    for (std::size_t i = 0; i < path.size(); ++i) {
        const render::Bounds& b = chunks[i / std::size_t(render::kDiskChunk)];
        const Sample& s = path.samples[i];
        EXPECT_GE(m.apply_x(s.x, s.y) - s.r, b.lo.x - 1e-12);
        EXPECT_LE(m.apply_y(s.x, s.y) + s.r, b.hi.y + 1e-12);
        EXPECT_GE(sample_time(place, path.dt, std::int64_t(i)), b.lo.z);
        EXPECT_LE(sample_time(place, path.dt, std::int64_t(i) + 1), b.hi.z + 1e-12);
    }
}

TEST(DiskLod, OutsideViewCullsOnlyWhatIsOutside) {
    const glm::mat4 identity(1.0f);  // clip volume = the cube [-1, 1]^3
    EXPECT_FALSE(render::outside_view(identity, glm::vec3(-0.5f), glm::vec3(0.5f)));
    EXPECT_FALSE(render::outside_view(identity, glm::vec3(0.9f), glm::vec3(3.0f)));   // straddles a side
    EXPECT_FALSE(render::outside_view(identity, glm::vec3(-5.0f), glm::vec3(5.0f)));  // holds the view
    EXPECT_TRUE(render::outside_view(identity, glm::vec3(1.5f, -0.5f, -0.5f), glm::vec3(2.0f, 0.5f, 0.5f)));
    EXPECT_TRUE(render::outside_view(identity, glm::vec3(-0.5f, -3.0f, -0.5f), glm::vec3(0.5f, -1.1f, 0.5f)));
    EXPECT_TRUE(render::outside_view(identity, glm::vec3(-0.5f, -0.5f, 1.2f), glm::vec3(0.5f, 0.5f, 2.0f)));
}

}  // namespace
}  // namespace mobb::test
