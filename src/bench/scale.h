// The scale workload: the avoiding crowd (`mobb crowd --select wander`) at the paper's density for growing
// numbers of agents, each size run with 1 thread and with `threads` threads, with its peak memory. Every
// run streams (CrowdOptions::sink): its digest and contact check are made as it goes and it keeps no
// record, so memory is the crowd's own (issue 29).
#pragma once
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "mobb/crowd/record/record.h"
#include "targets.h"

namespace mobb::bench {

struct ScaleOptions {
    std::string graph;
    std::vector<int> agents = {100, 1000, 10000, 100000};
    double seconds = 60;         ///< simulated
    double area_per_agent = 12;  ///< m^2: the paper's 100 agents in 30 x 40 m; the world is 3:4
    int threads = 0;             ///< the parallel runs; 0: every hardware thread
    int repeats = 3;             ///< runs per size and thread count (interleaved; medians reported)
    int once_from = 100000;      ///< sizes from here run one pair of runs, not `repeats` (minutes each)
    /// Sizes from here run only with `threads` threads, once (a million agents: about 1,300 s of CPU, 13
    /// minutes on 2 threads; bench/results/scale_million.md); their one-thread columns are empty.
    int parallel_only_from = 1000000;
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
    bool one_thread = true;          ///< false: only the parallel run was made (parallel_only_from)
    /// Bytes: peak resident memory of the process during the runs (the largest over the repeats; -1 when
    /// the system does not tell: peak_memory.h), and wall seconds of the whole run (placing the agents,
    /// simulating, the streamed contact check; medians).
    std::int64_t peak_bytes_1 = -1, peak_bytes_n = -1;
    double wall_seconds_1 = 0, wall_seconds_n = 0;
};

struct ScaleTable {
    std::string title;
    double seconds = 0;  ///< simulated, per run
    std::vector<ScaleRow> rows;
    std::map<std::string, std::string> notes;
    std::vector<Target> targets;
};

/// Runs the scale workload; `progress` (may be empty) gets the fraction done.
ScaleTable run_scale(const ScaleOptions& o, const std::function<void(double)>& progress = {});

/// FNV-1a (hex) of a record's decisions: every choice point (agent, frame, candidates with their
/// queries and answers, taken, fallback) in order, then each agent's committed clips. Equal records give
/// equal digests.
std::string record_digest(const crowd::Record& r);

/// The same digest made as a run streams (CrowdOptions::sink), keeping 8 bytes per agent: equal to
/// record_digest of the run's whole record.
class DigestSink : public crowd::RecordSink {
public:
    void begin(const crowd::Record& header) override;
    void choice(std::size_t index, const crowd::ChoicePoint& choice) override;
    void clip(int agent, const crowd::PlacedClip& clip) override;
    std::string digest() const;

private:
    std::uint64_t choices_ = 1469598103934665603ull;  // FNV-1a offset basis
    std::vector<std::uint64_t> clips_;                // per agent
};

}  // namespace mobb::bench
