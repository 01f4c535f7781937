// Viewer logic without a window: picking disks, stepping and playing a trace.
#include <cmath>
#include <set>

#include <gtest/gtest.h>

#include "panels.h"
#include "picking.h"
#include "render_test_util.h"
#include "scene.h"
#include "shortcuts.h"
#include "state.h"

namespace mobb::test {
namespace {

viewer::State walks() { return viewer::load_state(viewer::load_scene(test_scene("walks.json")), 4.0f / 3.0f); }

TEST(Picking, RayFromTheSideFindsTheDiskItCrosses) {
    viewer::State s = walks();
    const Path& path = s.clips[0].tree->path();
    const int i = 40;
    const Rigid2 m = Rigid2::of(s.places[0]);
    const Sample& smp = path.samples[i];
    const double x = m.apply_x(smp.x, smp.y), y = m.apply_y(smp.x, smp.y);
    const double t = sample_time(s.places[0], path.dt, i) + 0.5 * path.dt;
    // A horizontal ray at that instant, from far away through the disk's centre.
    const float h = float(t * s.scene.time_scale);
    const render::Ray ray{glm::vec3(float(x) - 100.0f, h, float(-y)), glm::vec3(1, 0, 0)};
    const viewer::Pick p = viewer::pick_disk(s, ray);
    ASSERT_GE(p.clip, 0);
    // The first disk entered is sample i of clip 0 or a disk of the other clip at the same instant.
    const Path& hit_path = s.clips[std::size_t(p.clip)].tree->path();
    const double t0 = sample_time(s.places[std::size_t(p.clip)], hit_path.dt, p.sample);
    EXPECT_LE(t0, t + 1e-9);
    EXPECT_GE(t0 + hit_path.dt, t - 1e-9);
    EXPECT_EQ(viewer::pick_disk(s, {glm::vec3(500, 1, 500), glm::vec3(0, -1, 0)}).clip, -1);
}

TEST(Picking, GroundPoint) {
    const auto g = viewer::ground_point({glm::vec3(1, 5, -2), glm::normalize(glm::vec3(0, -1, 0))});
    ASSERT_TRUE(g);
    EXPECT_NEAR(g->x, 1.0, 1e-6);
    EXPECT_NEAR(g->y, 2.0, 1e-6);
}

TEST(TracePlayer, StepsClampAndMoveTheCursor) {
    viewer::State s = walks();
    viewer::Ui ui;
    ASSERT_GT(s.trace.size(), 2u);
    viewer::go_to_step(s, ui, -5);
    EXPECT_EQ(s.scene.step, 0);
    viewer::go_to_step(s, ui, 1 << 20);
    EXPECT_EQ(s.scene.step, int(s.trace.size()) - 1);
    const double end = s.places[0].t0 + s.clips[0].tree->path().duration() + s.places[1].t0 + 10;
    EXPECT_GE(s.scene.cursor, 0.0);
    EXPECT_LE(s.scene.cursor, end);
    viewer::go_to_step(s, ui, 0);
    ui.playing = true;
    ui.rate = 10;
    viewer::update_playback(s, ui, 0.25);  // 2.5 steps at 10 per second
    EXPECT_EQ(s.scene.step, 2);
    viewer::update_playback(s, ui, 1e6);  // runs off the end and stops
    EXPECT_EQ(s.scene.step, int(s.trace.size()) - 1);
    EXPECT_FALSE(ui.playing);
}

}  // namespace
}  // namespace mobb::test

namespace mobb::viewer {
namespace {

TEST(Shortcuts, NoTwoShareAKey) {
    const std::vector<Shortcut>& keys = shortcuts();
    ASSERT_FALSE(keys.empty());
    for (std::size_t i = 0; i < keys.size(); ++i)
        for (std::size_t j = i + 1; j < keys.size(); ++j)
            EXPECT_FALSE(keys[i].key == keys[j].key && keys[i].shift == keys[j].shift)
                << keys[i].keys << " and " << keys[j].keys << " share a key";
}

TEST(Shortcuts, EveryCommandHasAKeyAndTheHelpListsIt) {
    std::set<Command> bound;
    for (const Shortcut& k : shortcuts()) {
        bound.insert(k.command);
        EXPECT_STRNE(k.keys, "");
        EXPECT_STRNE(k.what, "");
    }
    EXPECT_EQ(bound.size(), std::size_t(Command::ToggleHelp) + 1);
    for (const Gesture& g : gestures()) EXPECT_STRNE(g.what, "");
}

TEST(Shortcuts, CommandsSetTheirRequests) {
    State s;
    Ui ui;
    run_command(Command::TopView, s, ui);
    EXPECT_EQ(ui.request_view, viewer::ViewPreset::Top);
    run_command(Command::SideView, s, ui);
    EXPECT_EQ(ui.request_view, viewer::ViewPreset::Side);
    run_command(Command::FrameAll, s, ui);
    EXPECT_TRUE(ui.request_frame_all);
    run_command(Command::ToggleHelp, s, ui);
    EXPECT_TRUE(ui.show_help);
    run_command(Command::TogglePlay, s, ui);
    EXPECT_TRUE(ui.playing);
    run_command(Command::ToggleHelp, s, ui);
    EXPECT_FALSE(ui.show_help);
}

}  // namespace
}  // namespace mobb::viewer
