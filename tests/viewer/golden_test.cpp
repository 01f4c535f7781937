// Image-diff tests: each case renders a scene headless (OSMesa, llvmpipe, 128-bit vectors) and
// compares it with tests/golden/NAME.png. MOBB_UPDATE_GOLDENS=1 rewrites the goldens instead
// (cmake --build BUILD --target update_goldens).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "crowd_view.h"
#include "headless.h"
#include "image_diff.h"
#include "mobb/crowd/record/record_file.h"
#include "panels.h"
#include "render_test_util.h"
#include "scene.h"
#include "state.h"

namespace mobb::test {
namespace {

using viewer::Scene;
using viewer::State;

struct Case {
    std::string name;
    std::string scene;
    std::function<void(State&)> edit = [](State&) {};
    bool ui = false;
    bool help = false;  ///< with ui: the Shortcuts window open
    int width = 320, height = 240;
};

std::string golden_path(const std::string& name) { return std::string(MOBB_GOLDEN_DIR) + "/" + name + ".png"; }

render::Image render_case(const Case& c) {
    const Scene scene = viewer::load_scene(test_scene(c.scene));
    State state = viewer::load_state(scene, float(c.width) / float(c.height));
    c.edit(state);
    return viewer::render_headless(state, {c.width, c.height, c.ui, c.help});
}

bool updating() {
    const char* v = std::getenv("MOBB_UPDATE_GOLDENS");
    return v && std::string(v) == "1";
}

void check_image(const std::string& name, const render::Image& actual);

void check_golden(const Case& c) { check_image(c.name, render_case(c)); }

void check_image(const std::string& name, const render::Image& actual) {
    const Case c{name, ""};
    const std::string golden = golden_path(c.name);
    if (updating()) {
        render::write_png(golden, actual);
        std::cout << "updated " << golden << "\n";
        return;
    }
    if (!std::filesystem::exists(golden)) {
        const std::string base = write_failure(MOBB_TEST_OUT, c.name, {}, actual, {});
        FAIL() << golden << " is missing; actual image in " << base
               << ".actual.png (regenerate: target update_goldens)";
    }
    const render::Image expected = render::read_png(golden);
    const Tolerance tolerance;
    const Diff diff = compare(expected, actual, tolerance);
    if (!diff.matches(tolerance)) {
        const std::string base = write_failure(MOBB_TEST_OUT, c.name, expected, actual, diff);
        FAIL() << c.name << ": " << diff.differing << " pixels differ (" << diff.fraction * 100 << "%, allowed "
               << tolerance.fraction * 100 << "%; largest channel difference " << diff.largest << ", hard limit "
               << tolerance.hard << "); see " << base << ".expected.png, " << base << ".actual.png, " << base
               << ".diff.png";
    }
}

void level(State& s, render::Layers l) { s.scene.layers = l; }

render::Layers boxes_at(int lvl, int count = 1) {
    render::Layers l;
    l.boxes = true;
    l.level = lvl;
    l.levels = count;
    l.cursor = l.skeletons = l.trace = false;
    return l;
}

Case mobb_level(int lvl) {
    return {"mobb_level" + std::to_string(lvl), "long.json", [lvl](State& s) { level(s, boxes_at(lvl)); }};
}

TEST(Golden, SyntheticWalks) { check_golden({"synthetic_walks", "walks.json"}); }

TEST(Golden, DiskStacksOnly) {
    MOBB_NEEDS_MOCAP();
    check_golden({"disk_stacks", "pair.json"});
}

TEST(Golden, MobbLevel0) {
    MOBB_NEEDS_MOCAP();
    check_golden(mobb_level(0));
}

TEST(Golden, MobbLevel1) {
    MOBB_NEEDS_MOCAP();
    check_golden(mobb_level(1));
}

TEST(Golden, MobbLevel2) {
    MOBB_NEEDS_MOCAP();
    check_golden(mobb_level(2));
}

TEST(Golden, UmobbLevel1) {
    MOBB_NEEDS_MOCAP();
    check_golden({"umobb_level1", "long.json", [](State& s) {
                      s.scene.tree.type = TreeType::Umobb;
                      viewer::rebuild_trees(s);
                      level(s, boxes_at(1));
                  }});
}

/// A step in the middle of the query, neither its first test nor its answer, with both nodes shown.
TEST(Golden, TraceStepMidQuery) {
    MOBB_NEEDS_MOCAP();
    check_golden({"trace_step", "pair.json", [](State& s) {
                      ASSERT_TRUE(s.queried);
                      ASSERT_GE(s.trace.size(), 5u);
                      s.scene.step = int(s.trace.size()) / 2;
                      s.scene.layers.trace = true;
                      s.scene.layers.disks_translucent = true;
                  }});
}

TEST(Golden, TraceHit) {
    MOBB_NEEDS_MOCAP();
    check_golden({"trace_hit", "pair.json", [](State& s) {
                      ASSERT_TRUE(s.answer);
                      s.scene.step = int(s.trace.size()) - 1;
                      ASSERT_EQ(s.trace.back().outcome, TraceOutcome::Hit);
                      s.scene.layers.trace = true;
                      s.scene.layers.disks_translucent = true;
                  }});
}

TEST(Golden, CursorWithSkeletons) {
    MOBB_NEEDS_MOCAP();
    check_golden({"cursor_skeletons", "pair.json", [](State& s) {
                      s.scene.layers.cursor = s.scene.layers.skeletons = true;
                      s.scene.cursor = 2.2;
                  }});
}

TEST(Golden, UiPanels) {
    MOBB_NEEDS_MOCAP();
    Case c{"ui_panels", "pair.json", [](State& s) {
               s.scene.step = 4;
               s.scene.layers.trace = true;
           }};
    c.ui = true;
    c.width = 1024;
    c.height = 640;
    check_golden(c);
}

/// The Shortcuts window (F1 or ?) over the panels: every key and gesture of the viewer listed.
TEST(Golden, ShortcutsWindow) {
    Case c{"ui_shortcuts", "walks.json"};
    c.ui = c.help = true;
    c.width = 1024;
    c.height = 640;
    check_golden(c);
}

/// The window's first frame headless: the panels of `start` (null: those the state opens by default)
/// in their columns, everything framed in the viewport they leave. With `check_cut`, a failure for each
/// window whose text is cut; `windows` receives the panels' rectangles.
render::Image render_ui(State& s, int width, int height, const viewer::Ui* start = nullptr, bool check_cut = true,
                        std::vector<viewer::ImageRect>* windows = nullptr) {
    viewer::Ui ui;
    if (start)
        ui = *start;
    else
        ui.panels = viewer::default_panels(s);
    ui.request_frame_all = true;
    std::vector<std::string> cut;
    render::Image image = viewer::render_headless(s, {width, height, true, false, &ui, &cut, nullptr, windows});
    for (const std::string& line : cut)
        if (check_cut) ADD_FAILURE() << width << "x" << height << ": " << line;
    return image;
}

/// A scene's panels at a common screen size, two disks picked (which opens the Inspector, its ruler), a
/// mid-query step: the scene framed between the columns, no window's text cut.
void check_scene_ui(const std::string& name, int width, int height) {
    const Scene scene = viewer::load_scene(test_scene("pair.json"));
    State s = viewer::load_state(scene, float(width) / float(height));
    s.scene.layers.trace = true;
    viewer::Ui start;
    start.panels = viewer::default_panels(s);
    viewer::click_disk(s, start, {0, 100});
    viewer::click_disk(s, start, {1, 120});
    ASSERT_TRUE(start.panels.inspector);
    check_image(name, render_ui(s, width, height, &start));
}

TEST(Golden, UiAt1280x720) {
    MOBB_NEEDS_MOCAP();
    check_scene_ui("ui_1280x720", 1280, 720);
}

TEST(Golden, UiAt1920x1080) {
    MOBB_NEEDS_MOCAP();
    check_scene_ui("ui_1920x1080", 1920, 1080);
}

/// A crowd record's panels (Scene, Crowd) with its first agent's choice points listed.
void check_crowd_ui(const std::string& name, int width, int height) {
    const std::string record = crowd_record();
    ASSERT_FALSE(record.empty()) << "mobb crowd --record failed";
    State s = viewer::load_crowd_state(record, float(width) / float(height));
    viewer::select_choice(s, 0, -1);
    s.scene.cursor = 4.0;
    check_image(name, render_ui(s, width, height));
}

TEST(Golden, CrowdUiAt1280x720) {
    MOBB_NEEDS_MOCAP();
    check_crowd_ui("crowd_ui_1280x720", 1280, 720);
}

TEST(Golden, CrowdUiAt1920x1080) {
    MOBB_NEEDS_MOCAP();
    check_crowd_ui("crowd_ui_1920x1080", 1920, 1080);
}

/// Every panel open on a large screen: no window's text is cut (image not kept: the goldens above show
/// the layouts users see).
TEST(UiLayout, EveryPanelFitsAt1920x1080) {
    MOBB_NEEDS_MOCAP();
    const Scene scene = viewer::load_scene(test_scene("pair.json"));
    State s = viewer::load_state(scene, 1920.0f / 1080.0f);
    viewer::Ui start;
    for (const viewer::PanelInfo& p : viewer::panel_list()) start.panels.*p.open = true;
    viewer::click_disk(s, start, {0, 100});
    viewer::click_disk(s, start, {1, 120});
    render_ui(s, 1920, 1080, &start);
}

/// The crowd from the default (space-time) camera: every agent's skeleton stands on its disk at the
/// cursor (they need the mocap the graph was built from).
TEST(Golden, Crowd) {
    MOBB_NEEDS_MOCAP();
    const std::string record = crowd_record();
    ASSERT_FALSE(record.empty()) << "mobb crowd --record failed";
    State s = viewer::load_crowd_state(record, 320.0f / 240.0f);
    ASSERT_EQ(s.crowd->agents, 12);
    ASSERT_EQ(s.clips.size(), 12u);
    viewer::select_choice(s, 0, -1);
    s.scene.cursor = 4.0;
    check_image("crowd", viewer::render_headless(s, {320, 240, false}));
    EXPECT_EQ(viewer::skeleton_problem(*s.crowd), "");
}

/// Larger, so the skeletons read: the space-time view, and from above (the skeletons on their disks).
TEST(Golden, CrowdSkeletons) {
    MOBB_NEEDS_MOCAP();
    const std::string record = crowd_record();
    ASSERT_FALSE(record.empty()) << "mobb crowd --record failed";
    State s = viewer::load_crowd_state(record, 800.0f / 500.0f);
    viewer::select_choice(s, 0, -1);
    s.scene.cursor = 3.0;
    check_image("crowd_skeletons", viewer::render_headless(s, {800, 500, false}));
    s.camera.top();
    viewer::frame_all(s, 800.0f / 500.0f);
    check_image("crowd_skeletons_top", viewer::render_headless(s, {800, 500, false}));
    EXPECT_EQ(viewer::skeleton_problem(*s.crowd), "");
}

/// Looks at agent `agent` at the cursor from `distance` metres: its body fills the image.
void look_at_agent(State& s, int agent, float distance) {
    const crowd::Record& r = s.crowd->record();
    const auto k = std::int64_t(std::floor(s.scene.cursor / r.dt + 1e-9));
    const auto last = r.tracks[std::size_t(agent)].left_frame.value_or(r.frames) - 1;
    const auto* disk = crowd::window_disk(s.crowd->window, std::size_t(agent), std::min(k, last));
    ASSERT_TRUE(disk);
    const auto& at = *disk;
    s.camera.target = glm::vec3(float(at[1]), float(s.scene.cursor * s.scene.time_scale + 0.8), float(-at[2]));
    s.camera.distance = distance;
    s.camera.pitch = 15.0f;
}

/// Bodies (Layers::bodies): a shaded capsule per bone, so the crowd reads as people; near one agent,
/// a thin slice of the stacks around the cursor.
TEST(Golden, CrowdBodies) {
    MOBB_NEEDS_MOCAP();
    const std::string record = crowd_record();
    ASSERT_FALSE(record.empty()) << "mobb crowd --record failed";
    State s = viewer::load_crowd_state(record, 800.0f / 500.0f);
    viewer::select_choice(s, 0, -1);
    s.scene.cursor = 3.0;
    s.scene.window = 0.3;
    s.scene.layers.bodies = true;
    look_at_agent(s, 0, 9.0f);
    check_image("crowd_bodies", viewer::render_headless(s, {800, 500, false}));
    EXPECT_EQ(viewer::skeleton_problem(*s.crowd), "");
}

/// The clip start whose blend moves a pose the most two frames in (of the 7.5 a 0.25 s window lasts):
/// agent and frame, and that largest joint offset between the blended and the raw pose (metres).
struct BlendMoment {
    int agent = -1;
    std::int64_t frame = 0;
    double offset = 0;
};
BlendMoment largest_blend(crowd::CrowdPoser& blended, crowd::CrowdPoser& raw) {
    BlendMoment best;
    const crowd::Record& r = blended.record();
    std::vector<glm::dvec3> a, b;
    for (int agent = 0; agent < int(r.tracks.size()); ++agent)
        for (std::size_t c = 1; c < r.tracks[std::size_t(agent)].clips.size(); ++c) {
            const std::int64_t k = r.tracks[std::size_t(agent)].clips[c].start + 2;
            if (!blended.pose(agent, k, a) || !raw.pose(agent, k, b)) continue;
            for (std::size_t j = 0; j < a.size(); ++j)
                if (glm::length(a[j] - b[j]) > best.offset) best = {agent, k, glm::length(a[j] - b[j])};
        }
    return best;
}

/// A blend under way: the agent whose clip start is eased the most, two frames in, blended (what the
/// viewer shows) and the raw clip at the same moment (the pose it eases into) - the pair shows the offset.
TEST(Golden, CrowdBlendUnderWay) {
    MOBB_NEEDS_MOCAP();
    const std::string record = crowd_record();
    ASSERT_FALSE(record.empty()) << "mobb crowd --record failed";
    State s = viewer::load_crowd_state(record, 800.0f / 500.0f);
    viewer::select_choice(s, 0, -1);
    ASSERT_FALSE(viewer::agent_skeletons(*s.crowd, 0.0, {}).empty()) << viewer::skeleton_problem(*s.crowd);
    crowd::PoseBlend off;
    off.window = 0;
    crowd::FootLock free;
    free.on = false;
    auto raw = std::make_shared<crowd::CrowdPoser>(s.crowd->record(), s.crowd->poses, crowd::RigJoints::All, off, free);
    raw->use_samples(&s.crowd->window);
    const BlendMoment m = largest_blend(*s.crowd->poser, *raw);
    ASSERT_GE(m.agent, 0);
    EXPECT_GT(m.offset, 0.1) << "agent " << m.agent << " frame " << m.frame;  // visibly under way
    s.scene.cursor = (double(m.frame) + 0.5) * s.crowd->record().dt;
    s.scene.window = 0.3;
    s.scene.layers.bodies = true;
    look_at_agent(s, m.agent, 4.0f);
    const render::Image blended = viewer::render_headless(s, {400, 500, false});
    s.crowd->poser = raw;
    const render::Image unblended = viewer::render_headless(s, {400, 500, false});
    check_image("crowd_blend", blended);
    check_image("crowd_blend_raw", unblended);
}

/// Whether a query of a candidate is its clip hitting another agent's clip (one the trace can open).
bool clip_hit(const crowd::CandidateQuery& q) { return q.hit && q.mine == 0 && q.agent >= 0 && q.piece >= 0; }

/// The first choice point after the start that found a clear clip (no fallback) among a few candidates,
/// one of them rejected by another agent's clip (so the Crowd panel stays short), or -1.
int small_rejection(const crowd::Record& r) {
    for (std::size_t n = 0; n < r.choices.size(); ++n) {
        const auto& c = r.choices[n];
        if (c.frame > 0 && !c.fallback && c.candidates.size() <= 6 &&
            std::any_of(c.candidates.begin(), c.candidates.end(),
                        [](const auto& k) { return std::any_of(k.against.begin(), k.against.end(), clip_hit); }))
            return int(n);
    }
    return -1;
}

/// One agent's choice point with its candidates placed where the agent stood, and the panels.
TEST(Golden, CrowdChoicePoint) {
    MOBB_NEEDS_MOCAP();
    const std::string record = crowd_record();
    ASSERT_FALSE(record.empty()) << "mobb crowd --record failed";
    State s = viewer::load_crowd_state(record, 1280.0f / 720.0f);
    ASSERT_TRUE(s.crowd->graph) << s.crowd->graph_error;
    const int pick = small_rejection(crowd::load_record(record));
    ASSERT_GE(pick, 0);
    viewer::select_choice(s, -1, pick);
    const auto& c = s.crowd->selected;
    ASSERT_EQ(s.crowd->candidate_clips.size(), c.candidates.size());
    s.scene.cursor = double(c.frame) * s.crowd->record().dt;
    s.scene.layers.disks_translucent = true;
    s.camera.top();  // the "top" preset: the candidates fan out from the agent's disk
    // The candidates' rows are wider than the column: their list scrolls sideways (not cut text).
    check_image("crowd_choice", render_ui(s, 1280, 720));
}

/// A rejected candidate's first colliding query opened in the trace debugger, seen from above: the
/// panel lists the candidate's queries with the opened one selected, the trace shows its first step.
TEST(Golden, CrowdQueryOpened) {
    MOBB_NEEDS_MOCAP();
    const std::string record = crowd_record();
    ASSERT_FALSE(record.empty()) << "mobb crowd --record failed";
    State s = viewer::load_crowd_state(record, 1280.0f / 720.0f);
    ASSERT_TRUE(s.crowd->graph) << s.crowd->graph_error;
    const auto& r = s.crowd->record();
    const int pick = small_rejection(crowd::load_record(record));
    ASSERT_GE(pick, 0);
    viewer::select_choice(s, -1, pick);
    const auto& c = s.crowd->selected;
    int k = 0;
    auto has_clip_hit = [&](int i) {
        const auto& a = c.candidates[std::size_t(i)].against;
        return std::any_of(a.begin(), a.end(), clip_hit);
    };
    while (!has_clip_hit(k)) ++k;
    const auto& against = c.candidates[std::size_t(k)].against;
    int j = 0;
    while (std::size_t(j) < against.size() && !clip_hit(against[std::size_t(j)])) ++j;
    ASSERT_LT(std::size_t(j), against.size());
    std::string message;
    ASSERT_TRUE(viewer::open_candidate_query(s, k, j, &message)) << message;
    EXPECT_TRUE(s.answer) << message;
    s.scene.cursor = double(c.frame) * r.dt;
    s.camera.top();
    // Query, Trace and Recursion open with the query. Trace stands in the left column, under Scene and
    // over Recursion, so that at 720 rows both columns fit without a panel scrolling (text cut fails).
    std::vector<viewer::ImageRect> windows;
    check_image("crowd_query", render_ui(s, 1280, 720, nullptr, true, &windows));
    auto x_of = [&](const std::string& name) {
        const auto w = std::find_if(windows.begin(), windows.end(), [&](const auto& win) { return win.name == name; });
        return w == windows.end() ? -1.0f : w->rect.x;
    };
    EXPECT_EQ(x_of("Scene"), 0.0f);
    EXPECT_EQ(x_of("Trace"), 0.0f);
    EXPECT_EQ(x_of("Recursion"), 0.0f);
    EXPECT_GT(x_of("Query"), 640.0f);
    EXPECT_GT(x_of("Crowd"), 640.0f);
    // With the left column collapsed nothing moves: Trace is back in its own column, which scrolls.
    viewer::Ui collapsed;
    collapsed.panels = viewer::default_panels(s);
    collapsed.columns.left_collapsed = true;
    render_ui(s, 1280, 720, &collapsed, false, &windows);
    EXPECT_GT(x_of("Trace"), 640.0f);
    EXPECT_EQ(x_of("Scene"), -1.0f);
}

/// Moves agent 1 onto agent 0 at a third of the run (one contact); returns that frame.
std::size_t add_contact(State& s) {
    crowd::SampleWindow& w = s.crowd->window;  // every frame of the record
    const auto frame = std::size_t(s.crowd->record().frames / 3);
    auto& moved = w.samples[frame * w.width() + 1];
    moved[1] = w.samples[frame * w.width()][1] + 0.3;
    moved[2] = w.samples[frame * w.width()][2];
    viewer::mark_contacts(*s.crowd);
    ++s.revision;
    return frame;
}

/// A scenario record (doorway two-way: walls, the wall with its door, two goals) in space-time, and the
/// same with a contact drawn at the cursor: the record's two agents moved onto each other at one frame.
TEST(Golden, CrowdScenario) {
    const std::string record = scenario_record("doorway_two_way");
    ASSERT_FALSE(record.empty()) << "mobb crowd --scenario failed";
    State s = viewer::load_crowd_state(record, 640.0f / 480.0f);
    s.scene.layers.skeletons = false;  // no mocap needed
    const auto& r = s.crowd->record();
    ASSERT_EQ(r.world.obstacles.size(), 2u);
    ASSERT_TRUE(r.tracks[0].goals.size() == 1 && r.tracks[1].goals.size() == 1);
    s.scene.cursor = 0.5 * double(r.frames) * r.dt;
    // A crowd opens with a time window: only the slab of the run around the cursor is drawn.
    EXPECT_GT(s.scene.window, 0.0);
    EXPECT_LT(2 * s.scene.window, double(r.frames) * r.dt);
    check_image("crowd_scenario", viewer::render_headless(s, {640, 480, false}));
    // Agent 1 moved onto agent 0 at one frame: both disks ringed red there.
    const std::size_t frame = add_contact(s);
    ASSERT_EQ(s.crowd->contacts.size(), 1u);
    s.scene.cursor = (double(frame) + 0.5) * r.dt;
    s.camera.top();
    viewer::frame_all(s, 640.0f / 480.0f);
    check_image("crowd_scenario_contact", viewer::render_headless(s, {640, 480, false}));
}

/// The agents of evacuation_exit before the evacuation's door (x 0 to 8 m, |y| < 5 m) at time t: how many,
/// and how many of them stand (their root moved under 0.1 m in the second before).
std::pair<int, int> queue_at(const crowd::Record& r, double t) {
    const auto k = std::size_t(t / r.dt), before = std::size_t(1.0 / r.dt);
    int there = 0, standing = 0;
    for (const auto& track : r.tracks) {
        if (k >= track.samples.size()) continue;
        const auto &now = track.samples[k], &then = track.samples[k - before];
        if (now[1] < 0.5 || now[1] > 8 || std::abs(now[2]) > 5) continue;
        ++there;
        standing += std::hypot(now[1] - then[1], now[2] - then[2]) < 0.1;
    }
    return {there, standing};
}

/// A queue at a door in space-time (evacuation_exit, 30 agents through a 2.4 m door at x = 0): the camera
/// on the door and 8 m before it, six seconds either side of 18 s; agents waiting stand as upright disk
/// stacks behind those walking through, whose stacks lean toward the door (docs/crowd.md's picture).
TEST(Golden, CrowdQueueAtDoor) {
    const std::string record = scenario_record("evacuation_exit");
    ASSERT_FALSE(record.empty()) << "mobb crowd --scenario failed";
    State s = viewer::load_crowd_state(record, 640.0f / 480.0f);
    s.scene.layers.skeletons = false;  // no mocap needed
    const auto [there, standing] = queue_at(crowd::read_record_file(record).record, 18.0);
    EXPECT_GE(there, 10) << "a crowd before the door";
    EXPECT_GE(standing, 2) << "some of it waiting";
    s.scene.cursor = 18.0;
    s.scene.window = 6.0;
    s.scene.time_scale = 0.3;
    viewer::frame_region(s, -4, -5, 8, 5, 640.0f / 480.0f);
    check_image("crowd_queue", viewer::render_headless(s, {640, 480, false}));
}

/// Goal sequences seen from above (waypoints: each agent's two waypoints drawn small, its last goal
/// larger, in its colour), and agents that leave at their goal (fan_in_exit) in space-time: each disk
/// stack ends at the frame its agent left, and its goal is drawn until then.
TEST(Golden, CrowdGoalSequencesAndLeaving) {
    const std::string waypoints = scenario_record("waypoints");
    ASSERT_FALSE(waypoints.empty()) << "mobb crowd --scenario failed";
    State s = viewer::load_crowd_state(waypoints, 640.0f / 480.0f);
    s.scene.layers.skeletons = false;  // no mocap needed
    for (const auto& t : s.crowd->record().tracks) ASSERT_EQ(t.goals.size(), 3u);
    s.scene.window = 0;  // all of the run
    s.scene.cursor = 0;
    s.camera.top();
    viewer::frame_all(s, 640.0f / 480.0f);
    check_image("crowd_waypoints", viewer::render_headless(s, {640, 480, false}));

    const std::string exit = scenario_record("fan_in_exit");
    ASSERT_FALSE(exit.empty()) << "mobb crowd --scenario failed";
    State e = viewer::load_crowd_state(exit, 640.0f / 480.0f);
    e.scene.layers.skeletons = false;
    const auto& r = e.crowd->record();
    double last = 0;
    for (const auto& t : r.tracks) {
        ASSERT_TRUE(t.left_frame);
        last = std::max(last, double(*t.left_frame) * r.dt);
    }
    const auto prisms = viewer::crowd_prisms(*e.crowd, 0);
    const auto goal = std::find_if(prisms.begin(), prisms.end(), [](const auto& p) { return p.fill > 0.5f; });  // goals
    ASSERT_NE(goal, prisms.end());
    EXPECT_LE(goal->t1, last + 1e-9) << "a goal is drawn until its agent left";
    e.scene.window = 0;
    e.scene.cursor = last + 1;  // everyone has left: no disk at the cursor
    check_image("crowd_leaving", viewer::render_headless(e, {640, 480, false}));
}

/// The Crowd panel's plots of fallbacks and contacts over time (ImGui's PlotHistogram) at 1280x720:
/// the one contact of add_contact() stands as one bar a third of the way along.
TEST(Golden, CrowdEventPlots) {
    const std::string record = scenario_record("doorway_two_way");
    ASSERT_FALSE(record.empty()) << "mobb crowd --scenario failed";
    State s = viewer::load_crowd_state(record, 1280.0f / 720.0f);
    s.scene.layers.skeletons = false;  // no mocap needed
    add_contact(s);
    ASSERT_FALSE(s.crowd->marks.empty());
    s.scene.cursor = 0.5 * double(s.crowd->record().frames) * s.crowd->record().dt;
    std::vector<std::string> cut;
    check_image("crowd_plots", viewer::render_headless(s, {1280, 720, true, false, nullptr, &cut}));
    for (const std::string& line : cut) ADD_FAILURE() << line;
}

/// Disks coloured by clearance to the other clip (reversed cool-warm map: the overlap warm) and the
/// level-1 boxes by how often the query tested them, with both colour bars; 480 x 360 so they read.
TEST(Golden, ColourClearanceAndTests) {
    MOBB_NEEDS_MOCAP();
    Case c{"colour_clearance_tests", "pair.json", [](State& s) {
               ASSERT_TRUE(s.answer);
               s.scene.layers.disk_colour = render::DiskColour::Clearance;
               s.scene.layers.boxes = true;
               s.scene.layers.level = 1;
               s.scene.layers.box_colour = render::BoxColour::Tests;
           }};
    c.width = 480;
    c.height = 360;
    check_golden(c);
}

/// Synthetic walks (no mocap) with disks by speed on viridis and boxes by tightness.
TEST(Golden, ColourSpeedAndTightness) {
    Case c{"colour_speed_tightness", "walks.json", [](State& s) {
               s.scene.layers.disk_colour = render::DiskColour::Speed;
               s.scene.layers.box_colour = render::BoxColour::Tightness;
               s.scene.layers.trace = false;
           }};
    c.width = 480;
    c.height = 360;
    check_golden(c);
}

/// The time window: only +-0.6 s about the cursor drawn, cut by the clip planes.
TEST(Golden, TimeWindow) {
    MOBB_NEEDS_MOCAP();
    check_golden({"time_window", "pair.json", [](State& s) {
                      s.scene.cursor = 2.2;
                      s.scene.window = 0.6;
                      s.scene.layers.cursor = s.scene.layers.skeletons = true;
                  }});
}

/// A colouring changes the picture: the walks by time do not match the same view by clip colour, and
/// without the colour bar the right edge is the background's.
TEST(GoldenNegative, ColouringChangesTheImage) {
    const Scene scene = viewer::load_scene(test_scene("walks.json"));
    State s = viewer::load_state(scene, 320.0f / 240.0f);
    const render::Image plain = viewer::render_headless(s, {320, 240, false});
    s.scene.layers.disk_colour = render::DiskColour::Time;
    const render::Image timed = viewer::render_headless(s, {320, 240, false});
    const Tolerance tolerance;
    EXPECT_GT(compare(plain, timed, tolerance).fraction, 0.01);
    // The bar's middle band, 20 px from the right edge and 60 px down, is the map's middle colour.
    const glm::vec3 mid = render::colour_at(render::ColourMap::Viridis, 0.5) * 255.0f;
    const auto* px = timed.at(320 - 17, 60);
    EXPECT_NEAR(px[0], mid.r, 24);
    EXPECT_NEAR(px[1], mid.g, 24);
    EXPECT_NEAR(px[2], mid.b, 24);
    const auto* bg = plain.at(320 - 17, 60);
    EXPECT_GT(bg[0], 230);
}

/// The comparator must catch a real change: the level-1 scene with one more box level drawn.
TEST(GoldenNegative, OneMoreBoxLevelDoesNotMatch) {
    MOBB_NEEDS_MOCAP();
    if (updating()) GTEST_SKIP() << "goldens being regenerated";
    const render::Image expected = render::read_png(golden_path("mobb_level1"));
    Case changed{"mobb_level1_plus_one", "long.json", [](State& s) { level(s, boxes_at(1, 2)); }};
    const render::Image actual = render_case(changed);
    const Tolerance tolerance;
    const Diff diff = compare(expected, actual, tolerance);
    EXPECT_FALSE(diff.matches(tolerance)) << "one more box level went unnoticed: " << diff.fraction;
    EXPECT_GT(diff.fraction, 0.005);
}

TEST(Comparator, Tolerances) {
    render::Image a{4, 4, std::vector<std::uint8_t>(64, 100)};
    render::Image b = a;
    b.at(1, 1)[0] = 108;  // within the channel tolerance
    EXPECT_EQ(compare(a, b, {8, 0.0}).differing, 0);
    b.at(2, 2)[1] = 200;  // one pixel of 16 differs
    const Diff d = compare(a, b, {8, 0.0});
    EXPECT_EQ(d.differing, 1);
    EXPECT_EQ(d.largest, 100);
    EXPECT_FALSE(d.matches({8, 0.05}));
    EXPECT_TRUE(d.matches({8, 0.0625}));
    EXPECT_FALSE(d.matches({8, 0.0625, 99}));  // one pixel past the hard limit fails alone
    EXPECT_EQ(d.image.at(2, 2)[0], 255);
    render::Image c{2, 4, std::vector<std::uint8_t>(32, 100)};
    EXPECT_FALSE(compare(a, c, {255, 1.0}).matches({255, 1.0}));  // sizes differ
}

TEST(Comparator, WritesExpectedActualAndDiff) {
    render::Image a{4, 4, std::vector<std::uint8_t>(64, 100)}, b = a;
    b.at(0, 0)[2] = 0;
    const Diff d = compare(a, b, {});
    const std::string base = write_failure(std::string(MOBB_TEST_OUT) + "/comparator", "sample", a, b, d);
    for (const char* ext : {".expected.png", ".actual.png", ".diff.png"})
        EXPECT_TRUE(std::filesystem::exists(base + ext)) << base + ext;
}

}  // namespace
}  // namespace mobb::test
