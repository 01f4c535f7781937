// The viewer's new panels' logic without a window: the recursion rebuilt from a trace, picks and the
// ruler, opening files, the settings file's camera lines, the panel columns and the viewport they
// leave, which panels each kind of file opens, and the layout check itself.
#include <algorithm>
#include <filesystem>

#include <glm/matrix.hpp>

#include <gtest/gtest.h>

#include "crowd_view.h"
#include "grid_layer.h"
#include "headless.h"
#include "layout.h"
#include "panels.h"
#include "picking.h"
#include "recursion.h"
#include "render_test_util.h"
#include "scene.h"
#include "space.h"
#include "state.h"
#include "view_settings.h"

namespace mobb::test {
namespace {

viewer::State load(const std::string& scene) {
    return viewer::load_state(viewer::load_scene(test_scene(scene)), 4.0f / 3.0f);
}

/// Checks the recursion of the state's query: pairs partition the trace, each child pair is one step
/// down from its parent in A, B or both, and the hit is below the root.
void check_recursion(const viewer::State& s) {
    const Tree& a = *s.clips[std::size_t(s.scene.query_a)].tree;
    const Tree& b = *s.clips[std::size_t(s.scene.query_b)].tree;
    const viewer::Recursion r = viewer::recursion_of(s.trace, a, b);
    ASSERT_EQ(r.pair_of.size(), s.trace.size());
    ASSERT_FALSE(r.pairs.empty());
    EXPECT_EQ(r.pairs[0].parent, -1);
    EXPECT_EQ(r.pairs[0].events, int(s.trace.size()));  // everything hangs under the roots' pair
    int covered = 0;
    for (std::size_t k = 0; k < r.pairs.size(); ++k) {
        const viewer::NodePair& p = r.pairs[k];
        covered += p.end - p.first;
        for (int e = p.first; e < p.end; ++e) {
            EXPECT_EQ(r.pair_of[std::size_t(e)], int(k));
            EXPECT_EQ(s.trace[std::size_t(e)].node_a, p.node_a);
            EXPECT_EQ(s.trace[std::size_t(e)].node_b, p.node_b);
        }
        if (p.parent < 0) continue;
        const viewer::NodePair& up = r.pairs[std::size_t(p.parent)];
        EXPECT_EQ(up.outcome, TraceOutcome::Overlap) << "pair " << k;
        const auto down = [](const Tree& t, std::int32_t from, std::int32_t to) {
            const Node& n = t.nodes()[std::size_t(from)];
            return to == from || (!n.leaf() && (to == n.child || to == n.child + 1));
        };
        EXPECT_TRUE(down(a, up.node_a, p.node_a) && down(b, up.node_b, p.node_b)) << "pair " << k;
        EXPECT_LT(p.parent, int(k));
    }
    EXPECT_EQ(covered, int(s.trace.size()));
    if (s.answer) {
        ASSERT_GE(r.first_hit, 0);
        EXPECT_EQ(s.trace[std::size_t(r.first_hit)].outcome, TraceOutcome::Hit);
        EXPECT_TRUE(r.pairs[0].hit);
    } else {
        EXPECT_EQ(r.first_hit, -1);
    }
}

TEST(Recursion, SyntheticWalksQuery) {
    const viewer::State s = load("walks.json");
    ASSERT_TRUE(s.queried);
    check_recursion(s);
}

TEST(Recursion, RealClipsQueryWithAHit) {
    MOBB_NEEDS_MOCAP();
    const viewer::State s = load("pair.json");
    ASSERT_TRUE(s.answer);
    check_recursion(s);
}

TEST(Recursion, EventsHoldingASample) {
    const viewer::State s = load("walks.json");
    const Tree& a = *s.clips[0].tree;
    const std::vector<int> held = viewer::events_holding(s.trace, a, 0, 0);
    ASSERT_FALSE(held.empty());
    EXPECT_EQ(held.front(), 0);  // the root holds every sample
    for (int e : held) EXPECT_EQ(a.nodes()[std::size_t(s.trace[std::size_t(e)].node_a)].first, 0u);
}

/// A ray straight down through the middle of clip A's root box, from above everything: the box hit is
/// one the boxes layer draws, the ray's entry point lies on it, and a click selects that node's events.
TEST(Picking, BoxOfTheQueryUnderARay) {
    viewer::State s = load("walks.json");
    s.scene.layers.boxes = true;
    s.scene.layers.level = 0;
    const Obb3 root = transformed(s.clips[0].tree->box3(s.clips[0].tree->nodes()[0]), SpaceTimeRigid::of(s.places[0]));
    const glm::vec3 top = render::to_gl(root.center.x, root.center.y, 1e3, s.scene.time_scale);
    const render::Ray ray{top, glm::vec3(0, -1, 0)};
    const viewer::BoxPick b = viewer::pick_box(s, ray);
    ASSERT_GE(b.node, 0);
    const Tree& tree = *s.clips[std::size_t(b.clip)].tree;
    EXPECT_EQ(tree.nodes()[std::size_t(b.node)].level, 0);
    // The entry point, back in space-time, lies on the box: inside its slabs up to rounding.
    const Obb3 hit =
        transformed(tree.box3(tree.nodes()[std::size_t(b.node)]), SpaceTimeRigid::of(s.places[std::size_t(b.clip)]));
    const glm::dvec3 p(root.center.x, root.center.y, (double(top.y) - b.distance) / s.scene.time_scale);
    const glm::dvec3 local = glm::transpose(hit.axes) * (p - hit.center);
    for (int i = 0; i < 3; ++i) EXPECT_LE(std::fabs(local[i]), hit.half[i] + 1e-4) << i;
    s.scene.layers.boxes = false;
    EXPECT_EQ(viewer::pick_box(s, ray).node, -1);
    viewer::Ui ui;
    viewer::click_box(s, ui, b.clip, b.node);
    ASSERT_FALSE(ui.picked_events.empty());
    for (int e : ui.picked_events) {
        const TraceEvent& ev = s.trace[std::size_t(e)];
        EXPECT_EQ(b.clip == s.scene.query_a ? ev.node_a : ev.node_b, b.node);
    }
    EXPECT_EQ(s.scene.step, ui.picked_events.back());
}

TEST(Inspector, TwoClicksMeasureAndSurviveSteps) {
    viewer::State s = load("walks.json");
    viewer::Ui ui;
    viewer::click_disk(s, ui, {0, 10});
    EXPECT_EQ(ui.pick.clip, 0);
    EXPECT_EQ(ui.ruler.clip, -1);
    ASSERT_FALSE(ui.picked_events.empty());  // clip 0 is the query's A: its events are selected
    EXPECT_EQ(s.scene.step, ui.picked_events.back());
    viewer::click_disk(s, ui, {1, 30});
    EXPECT_EQ(ui.ruler.sample, 10);
    EXPECT_EQ(ui.pick.sample, 30);
    const auto a = viewer::disk_of(s, ui.ruler), b = viewer::disk_of(s, ui.pick);
    ASSERT_TRUE(a && b);
    const auto r = viewer::measure(s, ui.ruler, ui.pick);
    ASSERT_TRUE(r);
    EXPECT_NEAR(r->distance, std::hypot(a->centre.x - b->centre.x, a->centre.y - b->centre.y), 1e-12);
    EXPECT_NEAR(r->radii, a->r + b->r, 1e-12);
    EXPECT_NEAR(r->clearance, r->distance - r->radii, 1e-12);
    EXPECT_NEAR(r->time_gap, std::max({0.0, b->t0 - a->t1, a->t0 - b->t1}), 1e-12);
    EXPECT_GT(r->time_gap, 0.0);  // samples 10 and 30 at the same rate and start
    viewer::go_to_step(s, ui, 0);
    s.scene.cursor += 1.0;
    EXPECT_EQ(ui.pick.sample, 30);
    EXPECT_EQ(ui.ruler.sample, 10);
    EXPECT_FALSE(viewer::measure(s, ui.ruler, {1, 1 << 30}));
}

TEST(OpenFiles, AddedClipIsOfferedToTheQuery) {
    MOBB_NEEDS_MOCAP();
    viewer::State s = load("walks.json");
    const std::size_t before = s.clips.size();
    const std::string file = io::data_dir() + "/cmu/005_01.bvh";
    const int k = viewer::add_clip_file(s, file);
    EXPECT_EQ(k, int(s.scene.clips.size()) - 1);
    EXPECT_EQ(s.clips.size(), before + 1);
    EXPECT_EQ(s.places.size(), before + 1);
    EXPECT_EQ(s.clips[std::size_t(k)].name, "005_01.bvh");
    EXPECT_EQ(s.scene.clips.back().file, "cmu/005_01.bvh");
    EXPECT_TRUE(s.queried);
    EXPECT_THROW(viewer::add_clip_file(s, io::data_dir() + "/cmu/no_such.bvh"), io::LoadError);
    EXPECT_EQ(s.clips.size(), before + 1);
}

TEST(OpenFiles, FirstFileBecomesTheQuerysClip) {
    MOBB_NEEDS_MOCAP();
    viewer::Scene empty;
    empty.query_a = empty.query_b = -1;
    viewer::State s = viewer::load_state(empty, 1.0f);
    viewer::add_clip_file(s, io::data_dir() + "/cmu/007_01.bvh");
    viewer::add_clip_file(s, io::data_dir() + "/cmu/005_01.bvh");
    EXPECT_EQ(s.scene.query_a, 0);
    EXPECT_EQ(s.scene.query_b, 1);
    EXPECT_TRUE(s.queried);
}

/// What GLFW's drop callback leaves in the Ui: opened on the next frame, a bad file named.
TEST(OpenFiles, DroppedFilesOpenAndABadOneSaysWhy) {
    MOBB_NEEDS_MOCAP();
    viewer::State s = load("walks.json");
    const std::size_t before = s.clips.size();
    viewer::Ui ui;
    ui.dropped = {io::data_dir() + "/cmu/005_01.bvh", "/no/such/file.bvh"};
    viewer::open_dropped(s, ui);
    EXPECT_TRUE(ui.dropped.empty());
    EXPECT_EQ(s.clips.size(), before + 1);
    EXPECT_NE(ui.open_status.find("/no/such/file.bvh"), std::string::npos) << ui.open_status;
    EXPECT_TRUE(ui.panels.open);
}

/// The Open panel lists every format load_clip reads, not only BVH and glTF: the data folder's FBX
/// exports are listed (and its CSV paths and README are not), and one opens, clicked or dropped.
TEST(OpenFiles, FbxIsListedAndOpens) {
    MOBB_NEEDS_MOCAP();
    const std::string dir = io::data_dir();
    if (!std::filesystem::is_regular_file(dir + "/fbx/005_01.fbx")) GTEST_SKIP() << "no fbx/005_01.fbx in " << dir;
    const std::vector<std::string> files = viewer::list_clip_files(dir);
    EXPECT_TRUE(std::is_sorted(files.begin(), files.end()));
    for (const char* f : {"fbx/005_01.fbx", "cmu/005_01.bvh"})
        EXPECT_TRUE(std::binary_search(files.begin(), files.end(), std::string(f))) << f;
    for (const std::string& f : files) EXPECT_TRUE(io::is_clip_file(f)) << f;
    EXPECT_EQ(std::count_if(files.begin(), files.end(),
                            [](const std::string& f) { return std::filesystem::path(f).extension() == ".csv"; }),
              0);
    EXPECT_EQ(std::count(files.begin(), files.end(), "README.md"), 0);

    viewer::State s = load("walks.json");
    const std::size_t before = s.clips.size();
    viewer::Ui ui;
    ui.dropped = {dir + "/fbx/005_01.fbx"};
    viewer::open_dropped(s, ui);
    ASSERT_EQ(s.clips.size(), before + 1) << ui.open_status;
    EXPECT_EQ(s.scene.clips.back().file, "fbx/005_01.fbx");
    const viewer::LoadedClip& c = s.clips[s.scene.clips.size() - 1];
    EXPECT_EQ(c.name, "005_01.fbx");
    ASSERT_TRUE(c.clip);
    EXPECT_GT(c.clip->path.size(), 100u);  // 5 s of walking
    EXPECT_TRUE(s.queried);
    EXPECT_NE(ui.open_status.find("opened 005_01.fbx"), std::string::npos) << ui.open_status;
}

/// A crowd's clips are its agents: opening a file there is refused by name and changes nothing.
TEST(OpenFiles, RefusedInACrowdRecord) {
    const std::string record = scenario_record("doorway_two_way");
    ASSERT_FALSE(record.empty());
    viewer::State s = viewer::load_crowd_state(record, 1.0f);
    const std::size_t before = s.clips.size();
    try {
        viewer::add_clip_file(s, "/any/walk.bvh");
        FAIL() << "opened a file into a crowd";
    } catch (const io::LoadError& e) {
        EXPECT_NE(std::string(e.what()).find("/any/walk.bvh"), std::string::npos) << e.what();
    }
    EXPECT_EQ(s.clips.size(), before);
}

TEST(Settings, CameraLineRoundTrips) {
    render::Camera c;
    c.target = {1.5f, -2.25f, 3.0f};
    c.yaw = 12.5f, c.pitch = 80.0f, c.distance = 7.25f, c.fov = 40.0f;
    render::Camera back;
    ASSERT_TRUE(viewer::parse_camera_line(viewer::camera_line(c), back));
    EXPECT_EQ(back.target, c.target);
    EXPECT_EQ(back.yaw, c.yaw);
    EXPECT_EQ(back.distance, c.distance);
    EXPECT_FALSE(viewer::parse_camera_line("target=1,2 yaw=3", back));
    EXPECT_FALSE(viewer::parse_camera_line("target=1,2,3 yaw=0 pitch=0 distance=-1 fov=35", back));
}

TEST(Settings, FileInTheUsersConfigFolder) {
    const char* old = std::getenv("XDG_CONFIG_HOME");
    const std::string keep = old ? old : "";
    setenv("XDG_CONFIG_HOME", "/tmp/cfg", 1);
    EXPECT_EQ(viewer::settings_file(), "/tmp/cfg/mobb/imgui.ini");
    if (old)
        setenv("XDG_CONFIG_HOME", keep.c_str(), 1);
    else
        unsetenv("XDG_CONFIG_HOME");
}

/// The layout check must catch cut text: every panel open in a window too small for them.
TEST(UiLayout, SmallWindowCutsText) {
    viewer::State s = load("walks.json");
    viewer::Ui start;
    for (const viewer::PanelInfo& p : viewer::panel_list()) start.panels.*p.open = true;
    std::vector<std::string> cut;
    viewer::render_headless(s, {480, 300, true, false, &start, &cut});
    EXPECT_FALSE(cut.empty());
}

/// The viewport is the window between the columns and below the menu bar; collapsing a column, or
/// closing all of its panels, gives its room to the viewport.
TEST(PanelLayout, ViewportBetweenTheColumns) {
    viewer::State s;
    viewer::Ui ui;
    ui.window_size = {1280, 720};
    ui.menu_height = 19;
    viewer::Rect v = viewer::viewport(s, ui);  // a scene's panels: Scene, Recursion left; Query, Trace right
    EXPECT_EQ(v.x, ui.columns.left);
    EXPECT_EQ(v.y, 19.0f);
    EXPECT_EQ(v.width, 1280.0f - ui.columns.left - ui.columns.right);
    EXPECT_EQ(v.height, 701.0f);
    viewer::toggle_column(ui, viewer::Column::Left);
    EXPECT_EQ(viewer::viewport(s, ui).x, 0.0f);
    EXPECT_EQ(viewer::viewport(s, ui).width, 1280.0f - ui.columns.right);
    viewer::toggle_columns(ui);  // one was open: both collapse
    EXPECT_EQ(viewer::viewport(s, ui).width, 1280.0f);
    viewer::toggle_columns(ui);
    EXPECT_EQ(viewer::viewport(s, ui).x, ui.columns.left);
    ui.panels.query = ui.panels.trace = false;  // nothing left in the right column
    EXPECT_EQ(viewer::viewport(s, ui).width, 1280.0f - ui.columns.left);
    // The GL viewport counts rows from the bottom, in framebuffer pixels (here twice the window's).
    const render::Viewport gl = viewer::gl_viewport({300, 19, 650, 701}, {1280, 720}, {2560, 1440});
    EXPECT_EQ(gl.x, 600);
    EXPECT_EQ(gl.y, 0);
    EXPECT_EQ(gl.width, 1300);
    EXPECT_EQ(gl.height, 1402);
}

/// A scene opens Scene, Query, Trace and Recursion; a crowd Scene and Crowd, with the query panels once
/// a candidate's query is opened. A pick opens the Inspector unless the user closed it; the user's
/// choices go over the defaults.
TEST(PanelLayout, PanelsByWhatIsOpen) {
    const viewer::State scene = load("walks.json");
    const viewer::PanelsOpen p = viewer::default_panels(scene);
    EXPECT_TRUE(p.scene && p.query && p.trace && p.recursion);
    EXPECT_FALSE(p.fit || p.inspector || p.crowd || p.open);
    const std::string record = scenario_record("doorway_two_way");
    ASSERT_FALSE(record.empty());
    viewer::State crowd = viewer::load_crowd_state(record, 1.0f);
    const viewer::PanelsOpen c = viewer::default_panels(crowd);
    EXPECT_TRUE(c.scene && c.crowd);
    EXPECT_FALSE(c.query || c.trace || c.recursion || c.fit || c.inspector);
    crowd.crowd->opened_candidate = 0;
    const viewer::PanelsOpen q = viewer::default_panels(crowd);
    EXPECT_TRUE(q.query && q.trace && q.recursion);

    viewer::Ui ui;
    ui.panels = p;
    viewer::open_when_used(ui, &viewer::PanelsOpen::inspector);
    EXPECT_TRUE(ui.panels.inspector);
    viewer::choose_panel(ui, &viewer::PanelsOpen::inspector, false);
    viewer::open_when_used(ui, &viewer::PanelsOpen::inspector);
    EXPECT_FALSE(ui.panels.inspector);
    viewer::choose_panel(ui, &viewer::PanelsOpen::scene, false);
    const viewer::PanelsOpen kept = viewer::default_panels(crowd, ui.panel_choices);
    EXPECT_FALSE(kept.scene);
    EXPECT_FALSE(kept.inspector);
    EXPECT_TRUE(kept.crowd);
}

/// A crowd's Timeline stands in the bottom strip, between the columns; the viewport ends above it, and
/// collapsing the strip (or Tab, which collapses everything) gives its room back.
TEST(PanelLayout, TimelineInTheBottomStrip) {
    const std::string record = scenario_record("doorway_two_way");
    ASSERT_FALSE(record.empty());
    viewer::State s = viewer::load_crowd_state(record, 1.0f);
    viewer::Ui ui;
    ui.panels = viewer::default_panels(s);
    EXPECT_TRUE(ui.panels.timeline);
    ui.window_size = {1280, 720};
    ui.menu_height = 19;
    const float strip = viewer::strip_height(s, ui);
    EXPECT_GT(strip, 60.0f);
    EXPECT_LT(strip, 0.35f * 701.0f + 1.0f);
    const viewer::Rect v = viewer::viewport(s, ui);
    EXPECT_EQ(v.height, 701.0f - strip);
    viewer::place_panels(s, ui);
    const viewer::Rect t =
        ui.panel_rects[std::size_t(&viewer::panel_info(&viewer::PanelsOpen::timeline) - viewer::panel_list().data())];
    EXPECT_EQ(t.x, v.x);
    EXPECT_EQ(t.width, v.width);
    EXPECT_EQ(t.y, v.y + v.height);
    viewer::toggle_column(ui, viewer::Column::Bottom);
    EXPECT_EQ(viewer::viewport(s, ui).height, 701.0f);
    viewer::toggle_column(ui, viewer::Column::Bottom);
    viewer::toggle_columns(ui);
    EXPECT_EQ(viewer::viewport(s, ui).height, 701.0f);
    EXPECT_EQ(viewer::viewport(s, ui).width, 1280.0f);
    // A scene has no strip.
    const viewer::State scene = load("walks.json");
    viewer::Ui scene_ui;
    scene_ui.panels = viewer::default_panels(scene);
    EXPECT_EQ(viewer::strip_height(scene, scene_ui), 0.0f);
}

/// The span in normalised device coordinates of `points` under the camera, for the viewport's aspect.
struct Span {
    float x0 = 1, x1 = -1, y0 = 1, y1 = -1;
};
Span ndc_span(const viewer::State& s, const viewer::Rect& v, const std::vector<glm::vec3>& points) {
    const glm::mat4 m = s.camera.projection(v.aspect()) * s.camera.view();
    Span out;
    for (const glm::vec3& q : points) {
        const glm::vec4 p = m * glm::vec4(q, 1.0f);
        out.x0 = std::min(out.x0, p.x / p.w), out.x1 = std::max(out.x1, p.x / p.w);
        out.y0 = std::min(out.y0, p.y / p.w), out.y1 = std::max(out.y1, p.y / p.w);
    }
    return out;
}

/// In a headless image with the panels, frame all fits the scene's space-time box and the time axis
/// (at the grid's corner) into the viewport the columns leave: they project inside it, and the scene's
/// box reaches across most of it.
TEST(PanelLayout, FrameAllFillsTheViewport) {
    viewer::State s = load("walks.json");
    viewer::Ui start;
    start.panels = viewer::default_panels(s);
    start.request_frame_all = true;
    viewer::render_headless(s, {1280, 720, true, false, &start});
    start.window_size = {1280, 720};
    start.menu_height = 19;
    const viewer::Rect v = viewer::viewport(s, start);
    const render::Bounds b = render::scene_bounds(viewer::frame_of(s));
    glm::vec3 lo, hi;
    render::gl_bounds(b, s.scene.time_scale, lo, hi);
    std::vector<glm::vec3> box;
    for (int k = 0; k < 8; ++k) box.emplace_back(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z);
    const render::Bounds grid = render::grid_bounds(b);
    std::vector<glm::vec3> all = box;
    for (const double t : {grid.lo.z, grid.hi.z})
        all.push_back(render::to_gl(grid.lo.x, grid.lo.y, t, s.scene.time_scale));
    const Span a = ndc_span(s, v, all);
    EXPECT_GE(a.x0, -1.0f);
    EXPECT_LE(a.x1, 1.0f);
    EXPECT_GE(a.y0, -1.0f);
    EXPECT_LE(a.y1, 1.0f);
    const Span scene = ndc_span(s, v, box);
    EXPECT_GT(std::max(scene.x1 - scene.x0, scene.y1 - scene.y0), 1.6f) << "the scene fills most of the viewport";
}

}  // namespace
}  // namespace mobb::test
