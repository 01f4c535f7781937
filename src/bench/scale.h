// The scale workload: the avoiding crowd (`mobb crowd --select wander`) at the paper's density for growing
// numbers of agents, each size run with every thread count asked (1 and all by default), with its peak
// memory and the serial share of the frame step that the thread counts' times imply. Every
// run streams (CrowdOptions::sink): its digest and contact check are made as it goes and it keeps no
// record, so memory is the crowd's own (issue 29).
#pragma once
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
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
    /// Thread counts of each size's runs, the first the reference of the speed-ups (0: every hardware
    /// thread). The columns "_1" of a row are the first count's, "_n" the last count's.
    std::vector<int> threads = {1, 0};
    int repeats = 3;         ///< runs per size and thread count (interleaved; medians reported)
    int once_from = 100000;  ///< sizes from here run one pair of runs, not `repeats` (minutes each)
    /// Sizes from here run only with the last thread count, once (a million agents: about 1,300 s of CPU, 13
    /// minutes on 2 threads; bench/results/scale_million.md); their one-thread columns are empty.
    int parallel_only_from = 1000000;
    /// When set, one more (untimed, 1-thread, queries logged) run per size writes up to 5,000 of its
    /// queries, evenly spaced over the run, to "<save_queries>.<agents>" (save_query_set), for callgrind.
    std::string save_queries;
    std::uint64_t seed = 1;
};

/// One crowd size's runs with one thread count. Times are wall seconds, medians over the repeats.
struct ThreadRuns {
    int threads = 1;
    double sim_seconds = 0;        ///< CrowdSummary::seconds
    double cd_seconds = 0;         ///< CrowdSummary::cd_seconds: the frame step (choice points and commits)
    double wall_seconds = 0;       ///< the whole run (placing the agents, simulating, the streamed contact check)
    std::int64_t peak_bytes = -1;  ///< peak resident memory of the runs (largest; -1: unknown, peak_memory.h)
    double speedup = 0;            ///< the first thread count's sim_seconds / this one's (0: not run)
    /// Serial share of the frame step implied by its times (Karp and Flatt's experimentally determined
    /// serial fraction, serial_share() below); none for the first count or an equal one.
    std::optional<double> serial_share;
    std::string digest;  ///< of the first run (DigestSink)
    /// Steps of the frame step handed to the workers, per frame (CrowdSummary::parallel_steps): what
    /// each thread waits on; the same for any thread count from 2, none on one thread.
    double parallel_steps_per_frame = 0;
};

/// The share s of a step that does not run in parallel, by Amdahl's law t(p) = t(1) (s + (1 - s) / p),
/// from its wall times at two thread counts: t0 at p0 threads and t at p (Karp and Flatt, "Measuring
/// parallel processor performance", CACM 33(5), 1990, generalised from p0 = 1). It counts every cost that
/// does not shrink with threads: serial code, hand-offs, waits, a machine busy with other work. None when
/// p == p0 or a time is not positive.
std::optional<double> serial_share(int p0, double t0, int p, double t);

/// One crowd size. The "_1" columns are the runs with the first thread count, the "_n" ones with the
/// last (ScaleOptions::threads); every count's are in `by_threads`.
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
    int threads = 1;                              ///< the last thread count
    double speedup = 0;                           ///< cd_seconds_1 / cd_seconds_n (sim seconds when cd reads 0)
    bool identical = false;                       ///< same decisions and summary counters at every thread count
    std::string digest_1, digest_n;               ///< FNV-1a of the records' decisions (hex)
    bool one_thread = true;                       ///< false: only the parallel run was made (parallel_only_from)
    /// Bytes: peak resident memory of the process during the runs (the largest over the repeats; -1 when
    /// the system does not tell: peak_memory.h), and wall seconds of the whole run (placing the agents,
    /// simulating, the streamed contact check; medians).
    std::int64_t peak_bytes_1 = -1, peak_bytes_n = -1;
    double wall_seconds_1 = 0, wall_seconds_n = 0;
    std::vector<ThreadRuns> by_threads;  ///< per thread count, in ScaleOptions::threads' order (those run)
};

struct ScaleTable {
    std::string title;
    double seconds = 0;        ///< simulated, per run
    std::vector<int> threads;  ///< the thread counts run, every hardware thread resolved
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
    bool keeps_commits() const override { return true; }
    void begin(const crowd::Record& header) override;
    void choice(std::size_t index, const crowd::ChoicePoint& choice) override;
    void clip(int agent, const crowd::PlacedClip& clip) override;
    std::string digest() const;

private:
    std::uint64_t choices_ = 1469598103934665603ull;  // FNV-1a offset basis
    std::vector<std::uint64_t> clips_;                // per agent
};

}  // namespace mobb::bench
