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
#include "mobb/crowd/record.h"

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

/// Writes a query set (clips and queries) as text, for bench/workload_driver (callgrind). Throws
/// std::runtime_error when the file cannot be written.
void save_query_set(const QuerySet& set, const std::string& file);
/// Reads save_query_set()'s file. Throws std::runtime_error "FILE: ..." on any problem.
QuerySet load_query_set(const std::string& file);

/// One row: a method's mean time per query (microseconds, median over the timed passes) and mean work
/// per query (tests counted in a separate, untimed pass), share of positive answers, and answers that
/// differ from the reference (brute force) on the queries the method answered.
struct MethodRow {
    std::string method;
    double us_per_query = 0;
    double x_mobb = 0;                  ///< us_per_query / the "mobb" row's (0 when there is none)
    double tests2d = 0, tests3d = 0, samples = 0;
    double positive = 0;
    std::uint64_t queries = 0;          ///< answered in the untimed pass (agreement, positives, tests)
    std::uint64_t timed_queries = 0;    ///< per timed pass (a prefix of the queries for slow methods)
    std::uint64_t disagreements = 0;
    std::uint64_t extra = 0, missed = 0;  ///< of the disagreements: positive for this method only / for brute force only
    bool measured = true;               ///< false: the method could not run (see note)
    std::string note;
};

/// One of issue 5's targets as measured in the run: `measured` is a speed ratio (higher is better,
/// met when >= goal) unless `at_most`, then a cost ratio (met when <= goal).
struct Target {
    std::string what;                   ///< e.g. "mobb >= 25x faster than MOBB 1 level"
    double goal = 1, measured = 0;
    bool at_most = false;
    bool known = true;                  ///< false: not measurable in this run (see detail)
    bool ratio = true;                  ///< false: a count (e.g. contacts), printed without "x"
    std::string detail;                 ///< how measured, or why not
    bool met() const { return known && (at_most ? measured <= goal : measured >= goal); }
};
/// "measured 12.3x, goal >= 25x: MISSED (2.03x short)", or "met", or "not measured: ...".
std::string target_text(const Target& t);

struct BenchTable {
    std::string workload;                       ///< "table1", "table2", "synth42", "synth120"
    std::string title;
    std::vector<MethodRow> rows;
    std::map<std::string, std::string> notes;   ///< settings and measured context, as text
    std::vector<Target> targets;
};

/// Times every method on the same queries: `passes` timed passes, methods interleaved within each
/// pass so drifts of a shared machine hit every row alike. Slow methods (QueryMethod::slow()) are timed
/// on the first `slow_queries` queries only; FCL also answers only those in the untimed pass. The row
/// of the method named "brute force" (if any; it answers every query) is the reference for
/// disagreements; x_mobb is filled from the "mobb" row. Unavailable methods get an unmeasured row.
/// `progress` (may be empty) gets the fraction done.
std::vector<MethodRow> time_methods(const QuerySet& set, const std::vector<std::unique_ptr<QueryMethod>>& methods,
                                    int passes, const std::function<void(double)>& progress = {},
                                    std::size_t slow_queries = std::size_t(-1));

struct Table1Options {
    std::string graph;                  ///< motion graph file
    int agents = 100;
    double width = 30, height = 40, seconds = 120;
    std::uint64_t seed = 1;
    int passes = 21;                    ///< the crowd's queries take milliseconds per pass: many passes
    int n_min = 10;
    std::size_t slow_queries = 3000;    ///< brute force and FCL are timed on this many queries
    std::string save_queries;           ///< when set, the query set is written there (save_query_set)
};

/// Table 1: the crowd with random selection (the paper's timing workload); its choice-point queries are
/// replayed by every method of bench_methods() plus `extra`, and a frame-stepping baseline (see
/// frame_stepping.h) runs on the same choice points. Targets: mobb against the best scan (>= 1x) and
/// the paper's 1 level (>= 4x), and the crowd's collision-detection time per simulated second against
/// frame stepping's on the same choice points (>= 10x less).
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
    std::size_t slow_queries = 2000;    ///< brute force and FCL are timed on this many tests
    std::string workload;               ///< table name; empty: "table2", or "synth<seconds>" with synth
    std::string save_queries;           ///< when set, the query set is written there (save_query_set)
};

/// Table 2: `tests` identical random tests per method: a random pair of the motions, the second placed
/// with a random rotation, a translation uniform in a disk of radius R about the first's centre, and a
/// time offset uniform over the range where the two overlap in time; R chosen by bisection so the
/// share of root overlaps matches the target. Longest clips: every .bvh under <data>/cmu, longest first.
/// Methods: bench_methods() plus `extra`. Targets (issue 5): table2: mobb >= the best scan, >= 25x the
/// paper's 1 level, >= 20x FCL; synth42: >= 2x the best scan; synth120: >= 8x the best scan.
BenchTable run_table2(const Table2Options& o, std::vector<std::unique_ptr<QueryMethod>> extra = {},
                      const std::function<void(double)>& progress = {});

/// Markdown table (paper columns plus "x mobb" and positives), the targets, then the notes as a list.
std::string table_markdown(const BenchTable& t);
/// {"workload", "title", "targets": [...], "notes": {...}, "rows": [{"method", "us_per_query", "x_mobb", ...}]}.
std::string table_json(const BenchTable& t);
/// Horizontal bar chart of microseconds per query per method (stb_image_write). Throws
/// std::runtime_error when the file cannot be written.
void write_table_png(const BenchTable& t, const std::string& file);

/// Issue 5's scale workload: the avoiding crowd (`mobb crowd --select avoid`) at the paper's density
/// for growing numbers of agents, each run with 1 thread and with `threads` threads.
struct ScaleOptions {
    std::string graph;
    std::vector<int> agents = {100, 1000, 10000};
    double seconds = 60;                ///< simulated
    double area_per_agent = 12;         ///< m^2: the paper's 100 agents in 30 x 40 m; the world is 3:4
    int threads = 0;                    ///< the parallel runs; 0: std::thread::hardware_concurrency()
    int repeats = 3;                    ///< runs per size and thread count (interleaved; medians reported)
    /// When set, one more (untimed, 1-thread, queries logged) run per size writes up to 5,000 of its
    /// queries, evenly spaced over the run, to "<save_queries>.<agents>" (save_query_set), for callgrind.
    std::string save_queries;
    std::uint64_t seed = 1;
};

/// One crowd size. Times are wall seconds (medians over the repeats) of the runs with 1 thread ("_1")
/// and with `threads` ("_n").
struct ScaleRow {
    int agents = 0;
    double width = 0, height = 0;       ///< metres
    std::uint64_t choice_points = 0, candidates = 0, queries = 0, fallbacks = 0;
    std::uint64_t contacts_unexcused = 0;     ///< frame contacts outside fallbacks (1-thread run)
    double sim_seconds_1 = 0, sim_seconds_n = 0;  ///< CrowdSummary::seconds
    double cd_seconds_1 = 0, cd_seconds_n = 0;    ///< CrowdSummary::cd_seconds (0 until measured there)
    double cd_us_per_agent_second = 0;  ///< cd_seconds_1 * 1e6 / (agents * simulated seconds)
    double ratio_to_first = 0;          ///< cd_us_per_agent_second / the first row's
    double cd_us_per_query = 0;         ///< cd_seconds_1 * 1e6 / queries
    int threads = 1;
    double speedup = 0;                 ///< cd_seconds_1 / cd_seconds_n (sim seconds when cd reads 0)
    bool identical = false;             ///< same decisions and summary counters for 1 and `threads` threads
    std::string digest_1, digest_n;     ///< FNV-1a of the records' decisions (hex)
};

struct ScaleTable {
    std::string title;
    std::vector<ScaleRow> rows;
    std::map<std::string, std::string> notes;
    std::vector<Target> targets;
};

/// Runs the scale workload; `progress` (may be empty) gets the fraction done.
ScaleTable run_scale(const ScaleOptions& o, const std::function<void(double)>& progress = {});
/// FNV-1a (hex) of a record's decisions: every choice point (agent, frame, candidates with their
/// queries and answers, taken, fallback) and every committed clip. Equal records give equal digests.
std::string record_digest(const Record& r);
std::string scale_markdown(const ScaleTable& t);
/// {"workload": "scale", "title", "targets", "notes", "rows": [{"method": "mobb crowd N agents",
/// "us_per_query" (CD time per query), "agents", ...}]}.
std::string scale_json(const ScaleTable& t);
/// Bar chart of CD microseconds per agent per simulated second per crowd size.
void write_scale_png(const ScaleTable& t, const std::string& file);

}  // namespace mobb::crowd
