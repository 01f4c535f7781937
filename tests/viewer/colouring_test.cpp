// Colour maps and colourings: the maps' ends and interpolation, scales in either direction, group
// values for the level of detail, colouring names, and the viewer's per-sample and per-node values.
#include <cmath>

#include <gtest/gtest.h>

#include "colour_bar_layer.h"
#include "colour_map.h"
#include "colouring.h"
#include "disk_lod.h"
#include "frame.h"
#include "mobb/core/clearance.h"
#include "mobb/core/path.h"
#include "render_test_util.h"
#include "scene.h"
#include "state.h"
#include "viewer_error.h"

namespace mobb::test {
namespace {

using render::ColourMap;

void expect_colour(const glm::vec3& a, const glm::vec3& b, float tol = 1e-6f) {
    EXPECT_NEAR(a.r, b.r, tol);
    EXPECT_NEAR(a.g, b.g, tol);
    EXPECT_NEAR(a.b, b.b, tol);
}

TEST(ColourMap, EndsAndInterpolation) {
    for (ColourMap m : {ColourMap::Viridis, ColourMap::Diverging}) {
        const auto& t = render::colour_table(m);
        expect_colour(render::colour_at(m, 0.0), t.front());
        expect_colour(render::colour_at(m, 1.0), t.back());
        expect_colour(render::colour_at(m, -3.0), t.front());  // clamped
        expect_colour(render::colour_at(m, 7.0), t.back());
        expect_colour(render::colour_at(m, 0.5 / 32.0), 0.5f * (t[0] + t[1]));
        expect_colour(render::colour_at(m, std::nan("")), t.front());
    }
    // Viridis climbs in lightness (green channel, roughly) from dark blue to yellow.
    const auto& v = render::colour_table(ColourMap::Viridis);
    for (std::size_t i = 1; i < v.size(); ++i) EXPECT_GT(v[i].g, v[i - 1].g);
    // The diverging map is light in the middle and dark at both ends, blue first.
    const auto& d = render::colour_table(ColourMap::Diverging);
    const auto light = [](const glm::vec3& c) { return c.r + c.g + c.b; };
    EXPECT_GT(light(d[16]), light(d[0]) + 0.5f);
    EXPECT_GT(light(d[16]), light(d[32]) + 0.5f);
    EXPECT_GT(d[0].b, d[0].r);
    EXPECT_GT(d[32].r, d[32].b);
}

TEST(ColourMap, ScalesRunEitherWay) {
    render::ColourScale s{ColourMap::Viridis, 2.0, 6.0, "speed", "m/s"};
    EXPECT_DOUBLE_EQ(s.position(4.0), 0.5);
    EXPECT_DOUBLE_EQ(s.position(1.0), 0.0);
    EXPECT_DOUBLE_EQ(s.position(9.0), 1.0);
    render::ColourScale r{ColourMap::Diverging, 1.0, -1.0, "clearance", "m"};  // reversed
    EXPECT_DOUBLE_EQ(r.position(-1.0), 1.0);
    EXPECT_DOUBLE_EQ(r.position(0.5), 0.25);
    EXPECT_DOUBLE_EQ(r.least(), -1.0);
    EXPECT_DOUBLE_EQ(r.most(), 1.0);
    const render::ColourScale flat{ColourMap::Viridis, 3.0, 3.0, "", ""};
    EXPECT_DOUBLE_EQ(flat.position(8.0), 0.5);
    EXPECT_EQ(render::bar_label(0.5), "0.5");
    EXPECT_EQ(render::bar_label(1234.5), "1.23e+03");
}

TEST(ColourMap, GroupValuesMeanOrLeast) {
    const std::vector<float> v{1, 3, 5, 7, -2};
    EXPECT_EQ(render::group_values(v, 2, false), (std::vector<float>{2, 6, -2}));
    EXPECT_EQ(render::group_values(v, 2, true), (std::vector<float>{1, 5, -2}));
    EXPECT_EQ(render::group_values(v, 1, false), v);
    EXPECT_EQ(render::group_values(v, 8, true), (std::vector<float>{-2}));
}

TEST(Colouring, NamesRoundTrip) {
    for (int k = 0; k < render::kDiskColours; ++k)
        EXPECT_EQ(render::parse_disk_colour(to_string(render::DiskColour(k))), render::DiskColour(k));
    for (int k = 0; k < render::kBoxColours; ++k)
        EXPECT_EQ(render::parse_box_colour(to_string(render::BoxColour(k))), render::BoxColour(k));
    try {
        render::parse_disk_colour("hue");
        FAIL() << "expected an error";
    } catch (const std::invalid_argument& e) {
        EXPECT_EQ(std::string(e.what()), "disk colouring 'hue': expected one of clip, radius, speed, time, clearance");
    }
}

TEST(Colouring, SceneKeysRoundTripAndBadNamesNameTheKey) {
    viewer::Scene a = viewer::load_scene(test_scene("walks.json"));
    a.layers.disk_colour = render::DiskColour::Clearance;
    a.layers.box_colour = render::BoxColour::Tests;
    a.layers.colour_bar = false;
    const viewer::Scene b = viewer::parse_scene(viewer::scene_json(a), "s.json");
    EXPECT_EQ(b.layers.disk_colour, render::DiskColour::Clearance);
    EXPECT_EQ(b.layers.box_colour, render::BoxColour::Tests);
    EXPECT_FALSE(b.layers.colour_bar);
    try {
        viewer::parse_scene(nlohmann::json::parse(R"({"layers": {"box_colour": "size"}})"), "s.json");
        FAIL() << "expected an error";
    } catch (const viewer::ViewerError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "s.json.layers.box_colour: box colouring 'size': expected one of level, tightness, tests");
    }
}

/// The viewer's values are core's: times from sample_time, speeds from sample_speeds, clearances from
/// nearest_clearance, test counts adding up to the trace's tests; the frame points at them.
TEST(Colouring, ValuesComeFromCore) {
    const viewer::Scene scene = viewer::load_scene(test_scene("walks.json"));
    viewer::State s = viewer::load_state(scene, 1.0f);
    ASSERT_TRUE(s.queried);
    const Path& p1 = s.clips[1].tree->path();
    const auto times = viewer::sample_values(s, render::DiskColour::Time);
    ASSERT_EQ(times[1].size(), p1.size());
    EXPECT_FLOAT_EQ(times[1][10], float(sample_time(s.places[1], p1.dt, 10)));
    const auto speeds = viewer::sample_values(s, render::DiskColour::Speed);
    EXPECT_FLOAT_EQ(speeds[1][7], float(sample_speeds(p1)[7]));
    const auto gaps = viewer::sample_values(s, render::DiskColour::Clearance);
    const auto core = nearest_clearance({&s.clips[0].tree->path(), &p1}, s.places);
    EXPECT_FLOAT_EQ(gaps[0][40], float(core[0][40]));
    EXPECT_TRUE(viewer::sample_values(s, render::DiskColour::Clip)[0].empty());

    const auto tests = viewer::node_values(s, render::BoxColour::Tests);
    long tested = 0, counted = 0;
    for (const TraceEvent& e : s.trace) tested += e.test != TraceTest::Descend;
    for (float x : tests[0]) counted += long(x);
    EXPECT_EQ(counted, tested);

    s.scene.layers.disk_colour = render::DiskColour::Radius;
    const render::Frame f = viewer::frame_of(s);
    ASSERT_NE(f.clips[0].sample_values, nullptr);
    EXPECT_FLOAT_EQ((*f.clips[0].sample_values)[3], float(s.clips[0].tree->path().samples[3].r));
    EXPECT_EQ(f.disk_scale.label, "radius");
    EXPECT_EQ(f.disk_scale.unit, "m");
    const std::uint64_t before = f.colour_revision;
    s.scene.layers.disk_colour = render::DiskColour::Speed;
    const render::Frame g = viewer::frame_of(s);
    EXPECT_NE(g.colour_revision, before);
    EXPECT_EQ(g.disk_scale.lo, 0.0);
    EXPECT_GT(g.disk_scale.hi, 0.0);
}

}  // namespace
}  // namespace mobb::test
