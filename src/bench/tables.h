// The paper's experiments (section 5): Table 1, the crowd's own queries replayed by every method, and
// Table 2, identical random tests on long motions (and on motion-graph sequences: synth42, synth120).
// Every row is measured in the same run.
#pragma once
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "query_set.h"
#include "targets.h"
#include "timing.h"

namespace mobb::bench {

struct BenchTable {
    std::string workload;  ///< "table1", "table2", "synth42", "synth120"
    std::string title;
    std::vector<MethodRow> rows;
    std::map<std::string, std::string> notes;  ///< settings and measured context, as text
    std::vector<Target> targets;
};

struct Table1Options {
    std::string graph;  ///< motion graph file
    int agents = 100;
    double width = 30, height = 40, seconds = 120;
    std::uint64_t seed = 1;
    int passes = 21;  ///< the crowd's queries take milliseconds per pass: many passes
    int n_min = 10;
    std::size_t slow_queries = 3000;  ///< brute force and FCL are timed on this many queries
    std::string save_queries;         ///< when set, the query set is written there (save_query_set)
};

/// Table 1: the crowd with random selection (the paper's timing workload); its choice-point queries are
/// replayed by every method of table_methods(), and a frame-stepping baseline (frame_stepping.h) runs on
/// the same choice points. Targets: the circle sweep against the best scan (>= 1x) and the paper's 1
/// level (>= 4x), and the crowd's collision-detection time per simulated second against frame
/// stepping's on the same choice points (>= 10x less).
BenchTable run_table1(const Table1Options& o, const std::function<void(double)>& progress = {});

struct Table2Options {
    std::string graph;   ///< for --synth and for measuring the crowd's root-overlap share
    bool synth = false;  ///< motion-graph sequences instead of the longest clips
    int motions = 14;
    double synth_seconds = 42;  ///< length of each synthetic sequence
    int tests = 100000;
    double fps = 30;         ///< the clips are resampled to this rate
    double root_share = -1;  ///< target share of root overlaps; < 0: measure it on a crowd run
    int crowd_agents = 100;  ///< the crowd run used to measure it (random selection, 30 x 40 m)
    double crowd_seconds = 120;
    std::uint64_t seed = 1;
    int passes = 5;
    int n_min = 10;
    std::size_t slow_queries = 2000;  ///< brute force and FCL are timed on this many tests
    std::string workload;             ///< table name; empty: "table2", or "synth<seconds>" with synth
    std::string save_queries;         ///< when set, the query set is written there (save_query_set)
};

/// How Table 2's queries were made (for the table's notes).
struct Table2Setup {
    std::vector<std::string> names;   ///< one per motion
    double target = 0, achieved = 0;  ///< shares of root overlaps
    std::string target_source;
    double radius = 0;  ///< metres
};

/// Table 2's queries: `tests` random tests (random_tests) on the motions - the longest clips of the data,
/// or random walks in the graph with synth - at the radius whose share of root overlaps matches the
/// target (bisection); the target is measured on a crowd run unless given.
QuerySet table2_query_set(const Table2Options& o, Table2Setup* setup = nullptr);

/// Table 2 on table2_query_set(o), every method of table_methods(). Targets (issue 5): table2: the
/// circle sweep >= the best scan, >= 25x the paper's 1 level, >= 20x FCL; synth42: >= 2x the best
/// scan; synth120: >= 8x the best scan.
BenchTable run_table2(const Table2Options& o, const std::function<void(double)>& progress = {});

/// A workload by name with its default options, as `mobb bench` makes it: "table1" (the crowd's
/// queries), "table2", "synth42", "synth120" (Table 2's protocol), "seq42-30", "seq42-60"
/// (sequence42_set). `graph` is the motion graph file. Throws std::invalid_argument for another name.
QuerySet named_query_set(const std::string& name, const std::string& graph);

}  // namespace mobb::bench
