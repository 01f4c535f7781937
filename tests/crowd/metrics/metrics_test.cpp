// The crowd metrics on a record made by hand, with every figure worked out here from its definition.
#include <gtest/gtest.h>

#include <cmath>

#include "mobb/crowd/metrics/metrics.h"

namespace mobb::crowd {
namespace {

const std::string kGraph = std::string(MOBB_SOURCE_DIR) + "/assets/graphs/cmu_locomotion.json";

// Agent 0 stands at (2.01, 5); agent 1 walks through it along y = 5 at 1.5 m/s from x = 0.5 to its
// goal at (3.52, 5) (no contact or arrival falls exactly on a frame). Both r = 0.3, 60 frames at 30 Hz in a walled 10 x 10 m world.
Record passing(bool fallback) {
    Record r;
    r.dt = 1.0 / 30;
    r.frames = 60;
    r.world = {0, 0, 10, 10, true, {}};
    r.tracks.resize(2);
    for (int a = 0; a < 2; ++a) {
        r.tracks[std::size_t(a)].clips.push_back({0, 0, {}, a == 1 && fallback, a});
        for (int f = 0; f < 60; ++f) {
            const double t = f * r.dt;
            r.tracks[std::size_t(a)].samples.push_back({t, a == 0 ? 2.01 : 0.5 + 1.5 * t, 5.0, 0.3});
        }
    }
    r.tracks[1].goals = {{3.52, 5}};
    r.choices.resize(4);
    r.choices[2].fallback = fallback;
    return r;
}

TEST(Metrics, WorkedOutOnAHandMadeRecord) {
    const MotionGraph g = load_graph(kGraph);
    const CrowdMetrics m = crowd_metrics(passing(false), g);
    EXPECT_EQ(m.choice_points, 4u);
    EXPECT_EQ(m.fallbacks, 0u);
    // |x1 - 2.01| < 0.6 for t in (0.607, 1.407): frames 19..42.
    EXPECT_EQ(m.contacts, 24u);
    EXPECT_EQ(m.contacts_outside_fallbacks, 24u);
    EXPECT_NEAR(m.max_penetration, 0.59, 1e-12);  // at frame 30, 0.01 m apart
    EXPECT_EQ(m.samples_outside, 0u);
    EXPECT_EQ(m.obstacle_contacts, 0u);
    EXPECT_NEAR(m.mean_speed, 0.75, 1e-9);
    EXPECT_NEAR(m.graph_speed, graph_mean_speed(g), 0);
    EXPECT_NEAR(m.speed_ratio, 0.75 / graph_mean_speed(g), 1e-9);
    // Within 1 m of the goal from x > 2.52, frame 41 on; agent 1 no longer counts from then.
    EXPECT_EQ(m.goal_agents, 1);
    EXPECT_EQ(m.reached, 1);
    EXPECT_NEAR(m.mean_time_to_goal, 41.0 / 30, 1e-12);
    EXPECT_NEAR(m.path_ratio, 1.5 * (41.0 / 30) / 3.02, 1e-9);
    // 3.02 m straight from (0.5, 5) to (3.52, 5) at the walking clips' speed, against 41 frames.
    EXPECT_GT(graph_walking_speed(g), graph_mean_speed(g));
    EXPECT_NEAR(m.time_ratio, (41.0 / 30) * graph_walking_speed(g) / 3.02, 1e-9);
    // Agent 0 is idle all 60 frames, agent 1 never in its 41.
    EXPECT_NEAR(m.idle_share, 60.0 / 101, 1e-12);
    EXPECT_NEAR(m.longest_idle, 2.0, 1e-12);
    EXPECT_FALSE(m.passed);
    // Composite01: one collision each (x 50), time enabled (2 s; to the goal 41/30 s), kinetic energy
    // per 20 Hz frame (none standing; 27 frames of 1.125 walking). No acceleration: Composite02 equal.
    const double c1 = ((50 + 2.0) + (50 + 41.0 / 30 + 27 * 0.5 * 1.5 * 1.5)) / 2;
    EXPECT_NEAR(m.composite01, c1, 1e-9);
    EXPECT_NEAR(m.composite02, c1, 1e-6);
}

TEST(Metrics, FallbacksExcuseTheirContactsAndWallsCount) {
    const MotionGraph g = load_graph(kGraph);
    Record r = passing(true);
    const CrowdMetrics m = crowd_metrics(r, g);
    EXPECT_EQ(m.fallbacks, 1u);
    EXPECT_NEAR(m.fallback_share, 0.25, 1e-12);
    EXPECT_EQ(m.contacts, 24u);
    EXPECT_EQ(m.contacts_outside_fallbacks, 0u);
    // Agent 0 moved against the wall: its disk crosses x = 0 in every frame, its root outside in none.
    for (auto& s : r.tracks[0].samples) s[1] = 0.2;
    const CrowdMetrics w = crowd_metrics(r, g);
    EXPECT_EQ(w.obstacle_contacts, 60u);
    EXPECT_EQ(w.samples_outside, 0u);
    for (auto& s : r.tracks[0].samples) s[1] = -0.5;
    EXPECT_EQ(crowd_metrics(r, g).samples_outside, 60u);
    // Apart and at the goal: passed.
    Record ok = passing(false);
    for (auto& s : ok.tracks[0].samples) s[2] = 8;
    EXPECT_TRUE(crowd_metrics(ok, g).passed);
}

// A graph whose disks are centred on the body, made by hand: clip 0's root walks along +x at 0.6 m/s while
// its disk swings 0.1 m to either side every frame; clip 1's root stands while its disk drifts along +x
// at 0.3 m/s (a body turning on the spot). 60 samples at 30 Hz each; every disk holds its root.
MotionGraph swaying_graph() {
    MotionGraph g;
    g.fps = 30;
    g.centre = io::PathCentre::Enclosing;
    g.clips.resize(2);
    for (int k = 0; k < 2; ++k) {
        GraphClip& c = g.clips[std::size_t(k)];
        c.exit = 60;
        c.successors = {k};
        c.distances = {0};
        c.path.dt = g.dt();
        for (int i = 0; i < 60; ++i) {
            const glm::dvec2 root = k == 0 ? glm::dvec2(0.02 * i, 0) : glm::dvec2(0, 0);
            const Sample disk = k == 0 ? Sample{0.02 * i, i % 2 ? 0.1 : -0.1, 0.3} : Sample{0.01 * i, 0, 0.7};
            c.path.samples.push_back(disk);
            c.root.push_back(root);
        }
    }
    return g;
}

// Where the disks are centred on the body, how an agent moves is its root's: speed, idle, path length and
// SteerSuite's effort follow the root (placed as its clips are), not its disk's centre.
TEST(Metrics, MotionFollowsTheRootWhereDisksAreCentredOnTheBody) {
    const MotionGraph g = swaying_graph();
    Record r;
    r.dt = g.dt();
    r.frames = 60;
    r.world = {0, 0, 10, 10, false, {}};
    r.tracks.resize(2);
    for (int a = 0; a < 2; ++a) {
        AgentTrack& t = r.tracks[std::size_t(a)];
        const Placement place{1.0 + 5 * a, 2.0 + 5 * a, 0.5, 0};
        t.clips.push_back({a, 0, place, false, -1});
        const Rigid2 m = Rigid2::of(place);
        for (const Sample& s : g.clips[std::size_t(a)].path.samples)
            t.samples.push_back({double(t.samples.size()) * r.dt, m.apply_x(s.x, s.y), m.apply_y(s.x, s.y), s.r});
    }
    const CrowdMetrics m = crowd_metrics(r, g);
    EXPECT_NEAR(m.graph_speed, (0.02 * 59 / 2.0 + 0) / 2, 1e-9) << "the clips' roots: 1.18 m in 2 s, and none";
    EXPECT_NEAR(m.mean_speed, (0.6 + 0) / 2, 1e-9) << "the disks' centres would give (6.03 + 0.3) / 2";
    EXPECT_NEAR(m.idle_share, 0.5, 1e-12) << "agent 1's root stands all along; its disk drifts at 0.3 m/s";
    EXPECT_NEAR(m.longest_idle, 2.0, 1e-9);
    // The same record read as root-centred disks moves as the disks do.
    MotionGraph as_root = g;
    as_root.centre = io::PathCentre::Root;
    for (GraphClip& c : as_root.clips) c.root.clear();
    const CrowdMetrics d = crowd_metrics(r, as_root);
    EXPECT_GT(d.mean_speed, 3.0);
    EXPECT_EQ(d.idle_share, 0.0);
}

TEST(Metrics, JsonHasEveryFigure) {
    const std::string j = metrics_json(crowd_metrics(passing(false), load_graph(kGraph)));
    for (const char* key :
         {"fallback_share", "contacts", "max_penetration", "speed_ratio", "idle_share", "longest_idle", "reached",
          "mean_time_to_goal", "path_ratio", "composite01", "composite02", "passed"})
        EXPECT_NE(j.find(std::string("\"") + key + "\""), std::string::npos) << key;
}

}  // namespace
}  // namespace mobb::crowd
