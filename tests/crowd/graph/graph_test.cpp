// The committed motion graph: well formed, every clip has a successor, and every edge joins poses
// under the threshold - recomputed here from the mocap files.
#include <algorithm>
#include <cmath>
#include <map>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "data.h"
#include "mobb/crowd/graph/motion_graph.h"
#include "mobb/crowd/graph/pose_distance.h"

namespace mobb::crowd {
namespace {

const std::string kGraph = std::string(MOBB_SOURCE_DIR) + "/assets/graphs/cmu_locomotion.json";
const std::string kEnclosingGraph = std::string(MOBB_SOURCE_DIR) + "/assets/graphs/cmu_locomotion_enclosing.json";

TEST(MotionGraph, CommittedGraphIsWellFormed) {
    const MotionGraph g = load_graph(kGraph);
    ASSERT_GE(g.clips.size(), 40u);
    EXPECT_NEAR(g.dt(), 1.0 / 30.0, 1e-12);
    double total = 0;
    for (std::size_t k = 0; k < g.clips.size(); ++k) {
        const GraphClip& c = g.clips[k];
        SCOPED_TRACE("clip " + std::to_string(k));
        EXPECT_FALSE(c.successors.empty());
        EXPECT_EQ(c.successors.size(), c.distances.size());
        for (double d : c.distances) EXPECT_LT(d, g.threshold);
        EXPECT_EQ(int(c.path.size()), c.exit - c.first);
        EXPECT_GE(c.path.duration(), 0.8 - 1e-9);
        EXPECT_LE(c.path.duration(), 2.0 + 1e-9);
        EXPECT_EQ(c.path.samples.front().x, 0.0);  // root of the first sample at the origin
        EXPECT_EQ(c.path.samples.front().y, 0.0);
        EXPECT_EQ(g.sources[std::size_t(c.source)].file.rfind("cmu/", 0), 0u)
            << "data files are named relative to the data folder";
        total += c.path.duration();
    }
    const double mean = total / double(g.clips.size());
    EXPECT_GT(mean, 1.0);
    EXPECT_LT(mean, 1.5);
    EXPECT_FALSE(g.command.empty());
}

TEST(MotionGraph, EveryClipReachesEveryClip) {
    const MotionGraph g = load_graph(kGraph);
    for (std::size_t s = 0; s < g.clips.size(); ++s) {
        std::vector<bool> seen(g.clips.size(), false);
        std::vector<int> todo{int(s)};
        seen[s] = true;
        while (!todo.empty()) {
            const int u = todo.back();
            todo.pop_back();
            for (int v : g.clips[std::size_t(u)].successors)
                if (!seen[std::size_t(v)]) {
                    seen[std::size_t(v)] = true;
                    todo.push_back(v);
                }
        }
        EXPECT_EQ(std::count(seen.begin(), seen.end(), true), long(g.clips.size())) << "from clip " << s;
    }
}

TEST(MotionGraph, EdgesJoinMatchingPosesRecomputedFromMocap) {
    MOBB_REQUIRE_MOCAP();
    const MotionGraph g = load_graph(kGraph);
    std::map<int, PoseTrack> tracks;
    for (const GraphClip& c : g.clips) {
        if (tracks.count(c.source)) continue;
        const io::Clip clip = load_graph_source(g, c.source);
        tracks[c.source] = pose_track(clip, select_joints(clip.animation.skeleton));
    }
    int edges = 0;
    for (std::size_t u = 0; u < g.clips.size(); ++u)
        for (std::size_t k = 0; k < g.clips[u].successors.size(); ++k) {
            const GraphClip& a = g.clips[u];
            const GraphClip& b = g.clips[std::size_t(a.successors[k])];
            const double d = pose_distance(tracks[a.source], a.exit, tracks[b.source], b.first, g.window).distance;
            EXPECT_LT(d, g.threshold) << "edge " << u << " -> " << a.successors[k];
            EXPECT_NEAR(d, a.distances[k], 1e-6);
            ++edges;
        }
    EXPECT_GT(edges, int(g.clips.size()));
}

TEST(MotionGraph, PathsMatchTheMocapInTheClipFrame) {
    MOBB_REQUIRE_MOCAP();
    const MotionGraph g = load_graph(kGraph);
    std::map<int, io::Clip> sources;
    for (const GraphClip& c : g.clips) {
        if (!sources.count(c.source)) sources.emplace(c.source, load_graph_source(g, c.source));
        const io::Clip& clip = sources.at(c.source);
        // Distances between samples survive the rigid change of frame (up to the 1e-6 m rounding).
        const Sample& a0 = clip.path.samples[std::size_t(c.first)];
        for (std::size_t i = 0; i < c.path.size(); ++i) {
            const Sample& a = clip.path.samples[std::size_t(c.first) + i];
            const Sample& l = c.path.samples[i];
            ASSERT_NEAR(std::hypot(a.x - a0.x, a.y - a0.y), std::hypot(l.x, l.y), 1e-5);
            ASSERT_NEAR(a.r, l.r, 1e-6);
        }
    }
    EXPECT_THROW(load_graph_source(g, int(g.sources.size())), std::out_of_range);
}

// The same takes with each disk the smallest holding the body: the same clips, edges, exits and kinds
// (read from the root's reach), every disk no wider than the root's, 16 % narrower on average.
TEST(MotionGraph, EnclosingGraphKeepsTheClipsAndNarrowsTheirDisks) {
    const MotionGraph root = load_graph(kGraph), body = load_graph(kEnclosingGraph);
    EXPECT_EQ(root.centre, io::PathCentre::Root);
    ASSERT_EQ(body.centre, io::PathCentre::Enclosing);
    ASSERT_EQ(root.clips.size(), body.clips.size());
    EXPECT_EQ(kinds_of(root), kinds_of(body));
    double sum_root = 0, sum_body = 0;
    for (std::size_t k = 0; k < root.clips.size(); ++k) {
        const GraphClip &a = root.clips[k], &b = body.clips[k];
        SCOPED_TRACE("clip " + std::to_string(k));
        EXPECT_EQ(a.successors, b.successors);
        EXPECT_EQ(a.exit_x, b.exit_x);
        EXPECT_EQ(a.exit_heading, b.exit_heading);
        EXPECT_TRUE(a.root.empty());
        ASSERT_EQ(a.path.size(), b.path.size());
        ASSERT_EQ(b.root.size(), b.path.size());
        for (std::size_t i = 0; i < a.path.size(); ++i) {
            EXPECT_NEAR(root_at(b, i).x, root_at(a, i).x, 2e-6) << "the root graph's centres are the root";
            EXPECT_NEAR(root_at(b, i).y, root_at(a, i).y, 2e-6);
        }
        EXPECT_NEAR(root_reach_of(b), root_reach_of(a), 2e-6);
        for (std::size_t i = 0; i < a.path.size(); ++i) {
            EXPECT_LE(b.path.samples[i].r, a.path.samples[i].r + 1e-6);
            sum_root += a.path.samples[i].r;
            sum_body += b.path.samples[i].r;
        }
        EXPECT_LE(std::hypot(b.path.samples[0].x, b.path.samples[0].y), b.path.samples[0].r) << "holds the root";
    }
    EXPECT_LT(sum_body, 0.9 * sum_root);
}

// Its disks are those of io::path_of(..., PathCentre::Enclosing) in the clip's frame.
TEST(MotionGraph, EnclosingPathsMatchTheMocapInTheClipFrame) {
    MOBB_REQUIRE_MOCAP();
    const MotionGraph g = load_graph(kEnclosingGraph);
    std::map<int, std::pair<io::Clip, Path>> sources;
    for (const GraphClip& c : g.clips) {
        if (!sources.count(c.source)) {
            io::Clip clip = load_graph_source(g, c.source);
            Path body = io::path_of(clip.animation, clip.up, io::PathCentre::Enclosing);
            sources.emplace(c.source, std::make_pair(std::move(clip), std::move(body)));
        }
        const auto& [clip, body] = sources.at(c.source);
        const Sample& root0 = clip.path.samples[std::size_t(c.first)];
        for (std::size_t i = 0; i < c.path.size(); ++i) {
            const Sample& a = body.samples[std::size_t(c.first) + i];
            const Sample& l = c.path.samples[i];
            ASSERT_NEAR(std::hypot(a.x - root0.x, a.y - root0.y), std::hypot(l.x, l.y), 1e-5);
            ASSERT_NEAR(a.r, l.r, 1e-6);
        }
    }
}

// The clips an agent stops with: idle clips stand still and loop on themselves (exit snapped to the
// identity, having really drifted less than kIdleExit), clips in place turn on the spot, and from every
// clip a chain of at most three clips reaches an idle one.
TEST(MotionGraph, EveryClipCanStop) {
    const MotionGraph g = load_graph(kGraph);
    std::map<ClipKind, int> kinds;
    std::vector<int> steps(g.clips.size(), 1 << 20);
    for (int k = 0; k < int(g.clips.size()); ++k) {
        const GraphClip& c = g.clips[std::size_t(k)];
        const ClipKind kind = kind_of(c, k);
        ++kinds[kind];
        if (kind != ClipKind::Idle) continue;
        steps[std::size_t(k)] = 0;
        EXPECT_EQ(c.exit_x, 0.0);
        EXPECT_EQ(c.exit_y, 0.0);
        EXPECT_EQ(c.exit_heading, 0.0);
        EXPECT_LT(c.idle_drift, kIdleExit);
        EXPECT_LT(std::abs(c.idle_turn), kIdleTurn);
        EXPECT_NE(std::find(c.successors.begin(), c.successors.end(), k), c.successors.end()) << "loops on itself";
        for (const Sample& x : c.path.samples) EXPECT_LT(std::hypot(x.x, x.y), kIdleReach);
    }
    EXPECT_GE(kinds[ClipKind::Idle], 1);
    EXPECT_GE(kinds[ClipKind::InPlace], 4);
    EXPECT_GE(kinds[ClipKind::Slow], 2);
    EXPECT_GE(kinds[ClipKind::Walk], 40);
    for (bool changed = true; changed;) {  // steps to an idle clip along successors
        changed = false;
        for (std::size_t k = 0; k < g.clips.size(); ++k)
            for (int s : g.clips[k].successors)
                if (steps[std::size_t(s)] + 1 < steps[k]) steps[k] = steps[std::size_t(s)] + 1, changed = true;
    }
    for (std::size_t k = 0; k < g.clips.size(); ++k) EXPECT_LE(steps[k], 3) << "clip " << k;
}

TEST(MotionGraph, ChainingPlacesSuccessorAtExit) {
    const MotionGraph g = load_graph(kGraph);
    const GraphClip& c = g.clips.front();
    const Placement p{1.0, 2.0, 0.5, 3.0};
    const Placement n = g.next(p, 0);
    const Rigid2 m = Rigid2::of(p);
    EXPECT_NEAR(n.x, m.apply_x(c.exit_x, c.exit_y), 1e-12);
    EXPECT_NEAR(n.y, m.apply_y(c.exit_x, c.exit_y), 1e-12);
    EXPECT_NEAR(n.theta, 0.5 + c.exit_heading, 1e-12);
    EXPECT_NEAR(n.t0, 3.0 + c.path.duration(), 1e-12);
}

TEST(MotionGraph, RoundTripsThroughText) {
    const MotionGraph g = load_graph(kGraph);
    const MotionGraph h = graph_from_json(nlohmann::json::parse(graph_to_text(g)), "text");
    ASSERT_EQ(h.clips.size(), g.clips.size());
    for (std::size_t k = 0; k < g.clips.size(); ++k) {
        EXPECT_EQ(h.clips[k].successors, g.clips[k].successors);
        ASSERT_EQ(h.clips[k].path.size(), g.clips[k].path.size());
        EXPECT_EQ(h.clips[k].path.samples.back().x, g.clips[k].path.samples.back().x);
    }
}

TEST(MotionGraph, BadFilesNameThePlace) {
    try {
        graph_from_json(
            nlohmann::json::parse(R"({"fps": 30, "threshold": 0.1, "window": 5, "sources": [], "clips": [{}]})"),
            "g.json: graph");
        FAIL();
    } catch (const GraphError& e) {
        EXPECT_NE(std::string(e.what()).find("g.json: graph.clips[0]"), std::string::npos) << e.what();
    }
    EXPECT_THROW(load_graph("/nonexistent/graph.json"), GraphError);
}

TEST(MotionGraph, BuildsFromWalksTrimsTheStrayFrameAndConnects) {
    MOBB_REQUIRE_MOCAP();
    std::vector<std::string> files;
    for (const char* f : {"cmu/007_01.bvh", "cmu/007_02.bvh", "cmu/007_03.bvh", "cmu/007_04.bvh"})
        files.push_back(test::data_file(f));
    GraphBuildOptions o;
    o.threshold = 0.15;
    const MotionGraph g = build_motion_graph(files, o);
    ASSERT_EQ(g.sources.size(), 4u);
    EXPECT_EQ(g.sources[0].frame_begin, 0);
    EXPECT_EQ(g.sources[2].frame_begin, 1) << "007_03 starts with a stray T-pose frame";
    EXPECT_EQ(g.sources[2].file, "cmu/007_03.bvh");
    ASSERT_GE(g.clips.size(), 2u);
    for (const GraphClip& c : g.clips) {
        EXPECT_FALSE(c.successors.empty());
        EXPECT_GE(c.path.duration(), o.min_clip - 1e-9);
        EXPECT_LE(c.path.duration(), o.max_clip + 1e-9);
        EXPECT_GT(c.exit_x, 1.0) << "a walk goes forward, along +x";
    }
    EXPECT_EQ(graph_from_json(nlohmann::json::parse(graph_to_text(g)), "g").clips.size(), g.clips.size());
    // The same walks with the disks centred on the body: the same clips and exits, no disk wider, and the
    // centre and each root's reach kept through the file.
    o.centre = io::PathCentre::Enclosing;
    const MotionGraph body = build_motion_graph(files, o);
    ASSERT_EQ(body.clips.size(), g.clips.size());
    for (std::size_t k = 0; k < g.clips.size(); ++k) {
        EXPECT_EQ(body.clips[k].exit_x, g.clips[k].exit_x);
        EXPECT_NEAR(root_reach_of(body.clips[k]), root_reach_of(g.clips[k]), 2e-6);
        for (std::size_t i = 0; i < g.clips[k].path.size(); ++i)
            EXPECT_LE(body.clips[k].path.samples[i].r, g.clips[k].path.samples[i].r + 1e-6);
    }
    const MotionGraph read = graph_from_json(nlohmann::json::parse(graph_to_text(body)), "g");
    EXPECT_EQ(read.centre, io::PathCentre::Enclosing);
    EXPECT_EQ(read.clips[1].root, body.clips[1].root);
    EXPECT_EQ(kinds_of(read), kinds_of(g));
}

TEST(MotionGraph, BuildRejectsBadInput) {
    EXPECT_THROW(build_motion_graph({}, {}), GraphError);
    EXPECT_THROW(build_motion_graph({"/nonexistent/x.bvh"}, {}), io::LoadError);
}

TEST(PoseDistance, MatrixAgreesWithPairwiseAndIsRigidInvariant) {
    MOBB_REQUIRE_MOCAP();
    io::LoadOptions lo;
    lo.fps = 30;
    const io::Clip a = io::load_clip(test::data_file("cmu/007_01.bvh"), lo);
    const io::Clip b = io::load_clip(test::data_file("cmu/007_02.bvh"), lo);
    const PoseJoints j = select_joints(a.animation.skeleton);
    EXPECT_GE(j.joints.size(), 15u);
    const PoseTrack ta = pose_track(a, j), tb = pose_track(b, j);
    const std::vector<float> m = distance_matrix(ta, tb, 5);
    for (int fa : {0, 10, ta.frames - 1})
        for (int fb : {0, 7, tb.frames - 1})
            EXPECT_NEAR(m[std::size_t(fa) * std::size_t(tb.frames) + std::size_t(fb)],
                        pose_distance(ta, fa, tb, fb).distance, 1e-4);
    EXPECT_NEAR(pose_distance(ta, 20, ta, 20).distance, 0.0, 1e-6);
    // Moving and turning the whole clip changes nothing.
    PoseTrack moved = tb;
    for (glm::dvec3& p : moved.points)
        p = {std::cos(1.0) * p.x - std::sin(1.0) * p.y + 3, std::sin(1.0) * p.x + std::cos(1.0) * p.y - 2, p.z};
    EXPECT_NEAR(pose_distance(ta, 12, moved, 30).distance, pose_distance(ta, 12, tb, 30).distance, 1e-9);
    // Walking: heading agrees with the direction of travel.
    const glm::dvec2 d = ta.root.back() - ta.root.front();
    const double travel = std::atan2(d.y, d.x);
    EXPECT_LT(std::abs(std::remainder(ta.heading[std::size_t(ta.frames / 2)] - travel, 2 * 3.14159265358979)), 0.5);
}

}  // namespace
}  // namespace mobb::crowd
