// The pieces the benchmark workloads are made of, one generator each: the queries of a crowd run, the
// longest real clips, walks in the motion graph, the paper's random tests (Table 2), and two long real
// sequences under random placements (the micro-benchmarks). Shared by `mobb bench`, the Google
// Benchmark target and the callgrind driver, so every one of them measures the same queries.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "mobb/core/path.h"
#include "mobb/core/tree.h"
#include "mobb/crowd/graph/motion_graph.h"
#include "mobb/crowd/sim/crowd.h"
#include "query_set.h"

namespace mobb::bench {

/// A crowd's logged queries (CrowdOptions::log_queries) as a set: the graph's clip paths, the queries in
/// the order run.
QuerySet crowd_query_set(const crowd::MotionGraph& graph, const std::vector<crowd::LoggedQuery>& queries);

struct NamedPath {
    std::string name;
    Path path;
};

/// The `count` longest CMU clips (every .bvh under <data>/cmu, longest first, ties by name) resampled
/// to `fps`. Throws std::runtime_error without the data folder, io::LoadError for a bad file.
std::vector<NamedPath> longest_clips(int count, double fps);

/// `count` random walks in the motion graph, each its clips chained (MotionGraph::next) until it lasts
/// at least `seconds`; a random first clip, then random successors. Deterministic for a seed.
std::vector<NamedPath> graph_walks(const crowd::MotionGraph& graph, int count, double seconds, std::uint64_t seed);

/// The paper's random tests (Table 2): a random pair of clips, b rotated at random, moved so its centre
/// (mean position) lands uniformly in a disk of radius `radius` (metres) about a's centre, and shifted
/// in time uniformly over the offsets where the two overlap. Deterministic for a seed.
std::vector<ClipQuery> random_tests(const std::vector<Path>& clips, double radius, int count, std::uint64_t seed);

/// MOBB trees of the clips (n_min samples per leaf): their root boxes define "root overlap".
std::vector<Tree> mobb_trees(const std::vector<Path>& clips, int n_min = 10);
/// Share of the queries whose MOBB root boxes overlap (root_boxes_overlap); trees by clip id.
double root_share(const std::vector<Tree>& trees, const std::vector<ClipQuery>& queries);
/// The radius of random_tests() whose share of root overlaps matches `target`, by bisection over 30
/// steps on `calibration` tests (the share falls as the radius grows).
double radius_for_root_share(const std::vector<Path>& clips, const std::vector<Tree>& trees, double target,
                             int calibration, std::uint64_t seed);

/// Paths joined end to end: each part translated so its first sample sits on the previous part's
/// last sample, then cut to `seconds`. All parts share the first part's dt.
Path concatenate(const std::vector<Path>& parts, double seconds);

/// The micro-benchmarks' long-clip workload: two ~42 s real sequences at `fps` (clip 0 = 001_01 +
/// 001_08, clip 1 = 001_14 + 002_05 + 005_02) and 4096 queries of clip 0 at the origin against clip 1
/// translated by up to 4 m on each axis, any rotation, a time offset within half the duration. Random
/// walks of the same length stand in without the data folder; `source` (if not null) says which.
QuerySet sequence42_set(double fps, std::string* source = nullptr);

}  // namespace mobb::bench
