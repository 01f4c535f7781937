// The paper's experiments (section 5): Table 1, the crowd's own queries replayed by every method, and
// Table 2, identical random tests on long motions. Every row is measured in the same run.
#pragma once
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "mobb/core/path.h"
#include "mobb/crowd/query_methods.h"

namespace mobb::crowd {

/// One query to replay: clip a at pa against clip b at pb (clip ids index QuerySet::clips).
struct BenchQuery {
    int a = 0, b = 0;
    Placement pa, pb;
};

struct QuerySet {
    std::vector<Path> clips;
    std::vector<BenchQuery> queries;
};

/// One row: a method's mean time per query (microseconds, median over the timed passes) and mean work
/// per query (tests counted in a separate, untimed pass), share of positive answers, and answers that
/// differ from the first method marked as the reference (brute force).
struct MethodRow {
    std::string method;
    double us_per_query = 0;
    double tests2d = 0, tests3d = 0, samples = 0;
    double positive = 0;
    std::uint64_t queries = 0;
    std::uint64_t disagreements = 0;
    std::string note;
};

struct BenchTable {
    std::string workload;                       ///< "table1", "table2"
    std::string title;
    std::vector<MethodRow> rows;
    std::map<std::string, std::string> notes;   ///< settings and measured context, as text
};

/// Times every method on the same queries: `passes` timed passes, methods interleaved within each
/// pass so drifts of a shared machine hit every row alike. The row of the method named "brute force"
/// (if any) is the reference for disagreements. `progress` (may be empty) gets the fraction done.
std::vector<MethodRow> time_methods(const QuerySet& set, const std::vector<std::unique_ptr<QueryMethod>>& methods,
                                    int passes, const std::function<void(double)>& progress = {});

struct Table1Options {
    std::string graph;                  ///< motion graph file
    int agents = 100;
    double width = 30, height = 40, seconds = 120;
    std::uint64_t seed = 1;
    int passes = 21;                    ///< the crowd's queries take milliseconds per pass: many passes
    int n_min = 10;
};

/// Table 1: the crowd with random selection (the paper's timing workload); its choice-point queries are
/// replayed by every method of paper_methods() plus `extra`, and a frame-stepping baseline (see
/// frame_stepping.h) runs on the same choice points.
BenchTable run_table1(const Table1Options& o, std::vector<std::unique_ptr<QueryMethod>> extra = {},
                      const std::function<void(double)>& progress = {});

struct Table2Options {
    std::string graph;                  ///< for --synth and for measuring the crowd's root-overlap share
    bool synth = false;                 ///< motion-graph sequences instead of the longest clips
    int motions = 14;
    double synth_seconds = 42;          ///< length of each synthetic sequence
    int tests = 100000;
    double fps = 30;                    ///< the clips are resampled to this rate
    double root_share = -1;             ///< target share of root overlaps; < 0: measure it on a crowd run
    int crowd_agents = 100;             ///< the crowd run used to measure it (random selection, 30 x 40 m)
    double crowd_seconds = 120;
    std::uint64_t seed = 1;
    int passes = 5;
    int n_min = 10;
};

/// Table 2: `tests` identical random tests per method: a random pair of the motions, the second placed
/// with a random rotation, a translation uniform in a disk of radius R about the first's centre, and a
/// time offset uniform over the range where the two overlap in time; R chosen by bisection so the
/// share of root overlaps matches the target. Longest clips: every .bvh under <data>/cmu, longest first.
BenchTable run_table2(const Table2Options& o, std::vector<std::unique_ptr<QueryMethod>> extra = {},
                      const std::function<void(double)>& progress = {});

/// Markdown table (paper columns plus positives), with the notes as a list below.
std::string table_markdown(const BenchTable& t);
/// {"workload", "title", "notes": {...}, "rows": [{"method", "us_per_query", "tests2d", ...}]}.
std::string table_json(const BenchTable& t);
/// Horizontal bar chart of microseconds per query per method (stb_image_write). Throws
/// std::runtime_error when the file cannot be written.
void write_table_png(const BenchTable& t, const std::string& file);

}  // namespace mobb::crowd
