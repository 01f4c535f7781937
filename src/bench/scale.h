// The scale workload: the avoiding crowd (`mobb crowd --select avoid`) at the paper's density for growing
// numbers of agents, each size run with 1 thread and with `threads` threads.
#pragma once
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "mobb/crowd/record.h"
#include "targets.h"

namespace mobb::bench {

struct ScaleOptions {
    std::string graph;
    std::vector<int> agents = {100, 1000, 10000};
    double seconds = 60;         ///< simulated
    double area_per_agent = 12;  ///< m^2: the paper's 100 agents in 30 x 40 m; the world is 3:4
    int threads = 0;             ///< the parallel runs; 0: every hardware thread
    int repeats = 3;             ///< runs per size and thread count (interleaved; medians reported)
    /// When set, one more (untimed, 1-thread, queries logged) run per size writes up to 5,000 of its
    /// queries, evenly spaced over the run, to "<save_queries>.<agents>" (save_query_set), for callgrind.
    std::string save_queries;
    std::uint64_t seed = 1;
};

/// One crowd size. Times are wall seconds (medians over the repeats) of the runs with 1 thread ("_1")
/// and with `threads` ("_n").
struct ScaleRow {
    int agents = 0;
    double width = 0, height = 0;  ///< metres
    std::uint64_t choice_points = 0, candidates = 0, queries = 0, fallbacks = 0;
    std::uint64_t contacts_unexcused = 0;         ///< frame contacts outside fallbacks (1-thread run)
    double sim_seconds_1 = 0, sim_seconds_n = 0;  ///< CrowdSummary::seconds
    double cd_seconds_1 = 0, cd_seconds_n = 0;    ///< CrowdSummary::cd_seconds
    double cd_us_per_agent_second = 0;            ///< cd_seconds_1 * 1e6 / (agents * simulated seconds)
    double ratio_to_first = 0;                    ///< cd_us_per_agent_second / the first row's
    double cd_us_per_query = 0;                   ///< cd_seconds_1 * 1e6 / queries
    int threads = 1;
    double speedup = 0;              ///< cd_seconds_1 / cd_seconds_n (sim seconds when cd reads 0)
    bool identical = false;          ///< same decisions and summary counters for 1 and `threads` threads
    std::string digest_1, digest_n;  ///< FNV-1a of the records' decisions (hex)
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
std::string record_digest(const crowd::Record& r);

}  // namespace mobb::bench
