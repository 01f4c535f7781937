// The scale workload (scale.h): the avoiding crowd at the paper's density, 1 and all threads.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "mobb/crowd/sim/crowd.h"
#include "mobb/util/json_text.h"
#include "mobb/util/median.h"
#include "mobb/util/worker_pool.h"
#include "peak_memory.h"
#include "scale.h"
#include "workloads.h"

namespace mobb::bench {

using namespace crowd;  // the scale workload is a crowd run

namespace {

constexpr std::uint64_t kFnvBasis = 1469598103934665603ull;

// 64-bit FNV-1a over integers and doubles (bit patterns), into the running hash h.
void fnv(std::uint64_t& h, std::uint64_t v) {
    for (int k = 0; k < 8; ++k) {
        h ^= (v >> (8 * k)) & 0xffu;
        h *= 1099511628211ull;
    }
}

void fnv(std::uint64_t& h, double v) {
    std::uint64_t bits = 0;
    static_assert(sizeof bits == sizeof v);
    std::memcpy(&bits, &v, sizeof v);
    fnv(h, bits);
}

void hash_choice(std::uint64_t& h, const ChoicePoint& cp) {
    fnv(h, std::uint64_t(cp.agent));
    fnv(h, std::uint64_t(cp.frame));
    fnv(h, std::uint64_t(cp.taken));
    fnv(h, std::uint64_t(cp.fallback));
    fnv(h, cp.queries);
    fnv(h, cp.pruned);
    for (const Candidate& c : cp.candidates) {
        fnv(h, std::uint64_t(c.clip));
        fnv(h, std::uint64_t(c.leaves_world || c.meets_solid));  // one bit, as bench/results/scale.json has it
        fnv(h, std::uint64_t(c.hits));
        for (const CandidateQuery& q : c.against)
            fnv(h, (std::uint64_t(std::uint32_t(q.agent)) << 40) ^ (std::uint64_t(std::uint32_t(query_index(q))) << 8) ^
                       (std::uint64_t(q.piece + 1) << 1) ^ std::uint64_t(q.hit));
    }
}

void hash_clip(std::uint64_t& h, const PlacedClip& c) {
    fnv(h, std::uint64_t(c.clip));
    fnv(h, std::uint64_t(c.start));
    fnv(h, c.place.x);
    fnv(h, c.place.y);
    fnv(h, c.place.theta);
    fnv(h, std::uint64_t(c.fallback));
    fnv(h, std::uint64_t(c.choice));
}

std::string hex(std::uint64_t h) {
    char buf[20];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
    return buf;
}

// The world of `agents` agents at `area_per_agent` m^2 each, 3:4 like the paper's 30 x 40 m.
void world_for(int agents, double area_per_agent, double& width, double& height) {
    const double area = double(agents) * area_per_agent;
    width = std::sqrt(area * 3.0 / 4.0);
    height = std::sqrt(area * 4.0 / 3.0);
}

// The avoiding crowd of one size at the workload's density.
CrowdOptions crowd_options(const ScaleOptions& o, int agents) {
    CrowdOptions co;
    co.agents = agents;
    world_for(agents, o.area_per_agent, co.world.x1, co.world.y1);
    co.seconds = o.seconds;
    co.seed = o.seed;
    co.select = Selection::Wander;
    return co;
}

// The runs of one size, per thread count (slot): times, peak memory, digests and summaries.
struct Runs {
    explicit Runs(std::size_t counts)
        : sim(counts), cd(counts), wall(counts), peak(counts, -1), digests(counts), steps_per_frame(counts) {}
    std::vector<std::vector<double>> sim, cd, wall;
    std::vector<std::int64_t> peak;
    std::vector<std::vector<std::string>> digests;
    std::vector<double> steps_per_frame;  // of each count's last run
    std::vector<CrowdSummary> summaries;  // every run's, in order
};

// One streamed run (no record kept): its summary, digest, times and peak memory go into `runs`.
void timed_run(const MotionGraph& g, const NarrowPhase& narrow, const ScaleOptions& o, int agents, int threads,
               Runs& runs, std::size_t slot, const std::function<void(double)>& progress) {
    CrowdOptions co = crowd_options(o, agents);
    co.threads = threads;
    DigestSink digest;
    co.sink = &digest;
    reset_peak_memory();
    const auto start = std::chrono::steady_clock::now();
    const CrowdSummary s = run_crowd(g, narrow, co, progress).summary;
    runs.wall[slot].push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    runs.peak[slot] = std::max(runs.peak[slot], peak_memory_bytes());
    runs.sim[slot].push_back(s.seconds);
    runs.cd[slot].push_back(s.cd_seconds);
    runs.digests[slot].push_back(digest.digest());
    runs.steps_per_frame[slot] = double(s.parallel_steps) / std::max(1.0, std::round(o.seconds / g.dt()));
    runs.summaries.push_back(s);
}

// Every run made the same decisions: equal digests and counters.
bool identical(const Runs& runs) {
    const CrowdSummary& a = runs.summaries.front();
    std::string digest;
    for (const std::vector<std::string>& d : runs.digests)
        for (const std::string& x : d) {
            if (digest.empty()) digest = x;
            if (x != digest) return false;
        }
    for (const CrowdSummary& b : runs.summaries)
        if (a.queries != b.queries || a.hits != b.hits || a.contacts != b.contacts ||
            a.choice_points != b.choice_points || a.fallbacks != b.fallbacks)
            return false;
    return true;
}

// The columns of each thread count run, speed-ups and serial shares against the first.
std::vector<ThreadRuns> thread_columns(const Runs& runs, const std::vector<int>& threads) {
    std::vector<ThreadRuns> out;
    for (std::size_t k = 0; k < threads.size(); ++k) {
        if (runs.sim[k].empty()) continue;
        ThreadRuns c;
        c.threads = threads[k];
        c.sim_seconds = util::median(runs.sim[k]);
        c.cd_seconds = util::median(runs.cd[k]);
        c.wall_seconds = util::median(runs.wall[k]);
        c.peak_bytes = runs.peak[k];
        c.digest = runs.digests[k].front();
        c.parallel_steps_per_frame = runs.steps_per_frame[k];
        if (k == 0) {
            c.speedup = 1;
        } else if (!runs.sim[0].empty()) {  // the first count ran (not a parallel_only_from size)
            const ThreadRuns& first = out.front();
            c.speedup = c.sim_seconds > 0 ? first.sim_seconds / c.sim_seconds : 0.0;
            c.serial_share = serial_share(first.threads, first.cd_seconds, c.threads, c.cd_seconds);
        }
        out.push_back(c);
    }
    return out;
}

// The row's columns from the runs made.
void fill_row(ScaleRow& r, const Runs& runs, const ScaleOptions& o, const std::vector<int>& threads) {
    const CrowdSummary& s = runs.summaries.front();
    r.by_threads = thread_columns(runs, threads);
    r.identical = identical(runs);
    r.choice_points = s.choice_points;
    r.candidates = s.candidates;
    r.queries = s.queries;
    r.fallbacks = s.fallbacks;
    r.contacts_unexcused = s.contacts_unexcused;
    const ThreadRuns &first = r.by_threads.front(), &last = r.by_threads.back();
    r.digest_1 = r.one_thread ? first.digest : "";
    r.digest_n = last.digest;
    if (r.one_thread) {
        r.peak_bytes_1 = first.peak_bytes;
        r.sim_seconds_1 = first.sim_seconds;
        r.cd_seconds_1 = first.cd_seconds;
        r.wall_seconds_1 = first.wall_seconds;
    }
    r.peak_bytes_n = last.peak_bytes;
    r.sim_seconds_n = last.sim_seconds;
    r.cd_seconds_n = last.cd_seconds;
    r.wall_seconds_n = last.wall_seconds;
    const double cd = r.one_thread ? r.cd_seconds_1 : r.cd_seconds_n;
    r.cd_us_per_agent_second = cd * 1e6 / (double(r.agents) * o.seconds);
    r.cd_us_per_query = s.queries ? cd * 1e6 / double(s.queries) : 0.0;
    if (!r.one_thread) return;
    const bool timed = r.cd_seconds_1 > 0 && r.cd_seconds_n > 0;
    r.speedup = timed ? r.cd_seconds_1 / r.cd_seconds_n : r.sim_seconds_n > 0 ? r.sim_seconds_1 / r.sim_seconds_n : 0.0;
}

// One crowd size: rounds of runs, one per thread count in order, interleaved - `repeats` of them below
// once_from, one from there, only the last count's run from parallel_only_from; records compared by
// digest and counters; times are medians.
ScaleRow scale_row(const MotionGraph& g, const NarrowPhase& narrow, const ScaleOptions& o, int agents,
                   const std::vector<int>& threads, const std::function<void(double)>& progress) {
    ScaleRow r;
    r.agents = agents;
    r.threads = threads.back();
    r.one_thread = agents < o.parallel_only_from;
    world_for(agents, o.area_per_agent, r.width, r.height);
    Runs runs(threads.size());
    const int repeats = agents >= o.once_from ? 1 : std::max(1, o.repeats);
    const std::size_t from = r.one_thread ? 0 : threads.size() - 1;
    const double parts = double(repeats) * double(threads.size() - from);
    for (int k = 0; k < repeats; ++k)
        for (std::size_t slot = from; slot < threads.size(); ++slot) {
            const double done = double(k) * double(threads.size() - from) + double(slot - from);
            timed_run(g, narrow, o, agents, threads[slot], runs, slot, [&](double f) {
                if (progress) progress((done + f) / parts);
            });
        }
    fill_row(r, runs, o, threads);
    return r;
}

// The largest size timed on one thread (every size has one when the first has).
const ScaleRow& largest_timed(const ScaleTable& t) {
    for (auto r = t.rows.rbegin(); r != t.rows.rend(); ++r)
        if (r->one_thread) return *r;
    return t.rows.front();
}

// The row of 10,000 agents, the size issues 5 and 29 set their targets at (else the largest timed).
const ScaleRow& target_row(const ScaleTable& t) {
    for (const ScaleRow& r : t.rows)
        if (r.agents == 10000 && r.one_thread) return r;
    return largest_timed(t);
}

// Issue 5: the CD cost per agent stays within 1.5x of the smallest crowd's as the crowd grows.
Target cost_target(const ScaleTable& t) {
    const ScaleRow &first = t.rows.front(), &last = target_row(t);
    Target cost;
    cost.what = "CD cost per agent per simulated second at " + std::to_string(last.agents) + " agents within 1.5x of " +
                std::to_string(first.agents);
    cost.goal = 1.5;
    cost.at_most = true;
    cost.measured = last.ratio_to_first;
    const double sim_ratio = (last.sim_seconds_1 / last.agents) / std::max(1e-12, first.sim_seconds_1 / first.agents);
    cost.detail = "whole simulation (1 thread) per agent: " + util::fixed(sim_ratio, 2) + "x";
    if (first.cd_seconds_1 <= 0 || last.cd_seconds_1 <= 0) {
        cost.known = false;
        cost.detail = "CrowdSummary::cd_seconds reads 0; " + cost.detail;
    }
    return cost;
}

// Issue 29: threads at 10,000 agents (or the largest size timed on one thread), records identical.
Target speed_target(const ScaleTable& t) {
    const ScaleRow* at = &target_row(t);
    Target speed;
    speed.what = "choice points on " + std::to_string(at->threads) + " threads >= 1.8x faster at " +
                 std::to_string(at->agents) + " agents, records identical";
    speed.goal = 1.8;
    speed.measured = at->speedup;
    bool same = true;
    for (const ScaleRow& r : t.rows) same = same && r.identical;
    speed.detail = std::string(at->cd_seconds_n > 0 ? "CD" : "simulation") + " wall time; records " +
                   (same ? "identical at every size" : "DIFFER at some size");
    if (!same) speed.measured = 0;
    return speed;
}

// Issue 29's memory and time at 100,000 and 1,000,000 agents, on `threads` threads.
void add_large_targets(ScaleTable& t) {
    for (const ScaleRow& r : t.rows) {
        const bool million = r.agents >= 1000000;
        if (r.agents < 100000) continue;
        Target memory;
        memory.what = std::to_string(r.agents) + " agents: peak memory <= " + (million ? "16" : "2") + " GB";
        memory.goal = million ? 16 : 2;
        memory.at_most = true;
        memory.ratio = false;
        memory.measured = double(r.peak_bytes_n) / 1e9;
        memory.known = r.peak_bytes_n > 0;
        memory.detail = "GB, peak resident size of the " + std::to_string(r.threads) + "-thread run";
        t.targets.push_back(memory);
        Target time;
        time.what = std::to_string(r.agents) + (million ? " agents: wall <= 900 s" : " agents: faster than real time");
        time.goal = million ? 900 : t.seconds;
        time.at_most = true;
        time.ratio = false;
        time.measured = million ? r.wall_seconds_n : r.sim_seconds_n;
        time.detail = std::string(million ? "whole run" : "simulation") + " seconds on " + std::to_string(r.threads) +
                      " threads for " + util::fixed(t.seconds, 0) + " s simulated";
        t.targets.push_back(time);
    }
}

void add_scale_targets(ScaleTable& t) {
    t.targets.push_back(cost_target(t));
    Target contacts;
    contacts.what = "no contacts outside fallbacks (all sizes)";
    contacts.goal = 0;
    contacts.at_most = true;
    contacts.ratio = false;
    for (const ScaleRow& r : t.rows) contacts.measured += double(r.contacts_unexcused);
    contacts.detail = "frame-by-frame check of every run, as it streams";
    t.targets.push_back(contacts);
    t.targets.push_back(speed_target(t));
    add_large_targets(t);
}

// The untimed logged run of one size: a sample of its queries for bench/callgrind_workload.sh.
void save_scale_queries(const MotionGraph& g, const NarrowPhase& narrow, const ScaleOptions& o, int agents) {
    CrowdOptions co = crowd_options(o, agents);
    co.log_queries = true;
    const CrowdRun run = run_crowd(g, narrow, co);
    const std::size_t n = run.queries.size(), keep = std::min<std::size_t>(n, 5000);
    std::vector<LoggedQuery> sample;
    for (std::size_t k = 0; k < keep; ++k) sample.push_back(run.queries[k * n / keep]);
    save_query_set(crowd_query_set(g, sample), o.save_queries + "." + std::to_string(agents));
}

// "1 and 2", "1, 2 and 4": the thread counts in words.
std::string count_list(const std::vector<int>& counts) {
    std::string out;
    for (std::size_t k = 0; k < counts.size(); ++k)
        out += (k == 0 ? "" : k + 1 == counts.size() ? " and " : ", ") + std::to_string(counts[k]);
    return out;
}

}  // namespace

std::string record_digest(const Record& r) {
    DigestSink sink;
    sink.begin(r);
    for (std::size_t k = 0; k < r.choices.size(); ++k) sink.choice(k, r.choices[k]);
    for (std::size_t a = 0; a < r.tracks.size(); ++a)
        for (const PlacedClip& c : r.tracks[a].clips) sink.clip(int(a), c);
    return sink.digest();
}

void DigestSink::begin(const Record& header) { clips_.assign(header.tracks.size(), kFnvBasis); }

void DigestSink::choice(std::size_t /*index*/, const ChoicePoint& choice) { hash_choice(choices_, choice); }

void DigestSink::clip(int agent, const PlacedClip& clip) { hash_clip(clips_.at(std::size_t(agent)), clip); }

std::string DigestSink::digest() const {
    std::uint64_t h = choices_;
    for (std::uint64_t a : clips_) fnv(h, a);
    return hex(h);
}

std::optional<double> serial_share(int p0, double t0, int p, double t) {
    if (p == p0 || p0 < 1 || p < 1 || !(t0 > 0) || !(t > 0)) return std::nullopt;
    // t / t0 = (s + (1 - s) / p) / (s + (1 - s) / p0), solved for s.
    const double ratio = t / t0, inv0 = 1.0 / double(p0), inv = 1.0 / double(p);
    return (inv - ratio * inv0) / (ratio * (1.0 - inv0) - (1.0 - inv));
}

ScaleTable run_scale(const ScaleOptions& o, const std::function<void(double)>& progress) {
    if (o.agents.empty()) throw std::invalid_argument("scale: no crowd sizes");
    if (o.threads.empty()) throw std::invalid_argument("scale: no thread counts");
    const MotionGraph g = load_graph(o.graph);
    const NarrowPhase narrow = NarrowPhase::sweep(g);
    std::vector<int> counts;
    for (int n : o.threads) counts.push_back(n > 0 ? n : util::WorkerPool::hardware_threads());
    const int threads = counts.back();
    double total = 0, done = 0;
    for (int n : o.agents) total += double(n);
    ScaleTable t;
    t.seconds = o.seconds;
    t.threads = counts;
    for (int n : o.agents) {
        t.rows.push_back(scale_row(g, narrow, o, n, counts, [&](double f) {
            if (progress) progress((done + f * n) / total);
        }));
        done += double(n);
        if (!o.save_queries.empty()) save_scale_queries(g, narrow, o, n);
    }
    for (ScaleRow& r : t.rows)
        r.ratio_to_first = r.one_thread && t.rows.front().cd_us_per_agent_second > 0
                               ? r.cd_us_per_agent_second / t.rows.front().cd_us_per_agent_second
                               : 0;
    add_scale_targets(t);
    const std::string first = std::to_string(counts.front()), list = count_list(counts);
    t.title = "Scale: avoiding crowd at the paper's density (" + util::fixed(o.area_per_agent, 0) +
              " m^2 per agent), " + util::fixed(o.seconds, 0) + " s simulated, " + list + " threads";
    t.notes["graph"] = o.graph;
    t.notes["crowd"] =
        "mobb crowd --select wander, seed " + std::to_string(o.seed) + ", world 3:4 growing with the agents";
    t.notes["CD time"] = "CrowdSummary::cd_seconds (broad + narrow phase wall time inside run_crowd)";
    t.notes["speed-up"] = first + "-thread time / " + std::to_string(threads) +
                          "-thread time: CD seconds when measured, else simulation seconds; in the thread table, "
                          "simulation seconds over the " +
                          first + "-thread run's";
    t.notes["serial share"] =
        "of the frame step (CD seconds), implied by its time at each thread count against " + first +
        " thread(s) by Amdahl's law (Karp-Flatt metric): serial code, the pool's hand-offs and waits, and other work "
        "on a shared machine all count";
    t.notes["parallel steps"] =
        "CrowdSummary::parallel_steps per frame: the frame step's loops handed to the worker pool, each a wake and a "
        "wait on every thread (the same count for any number of threads from 2; none on one)";
    t.notes["identical"] =
        "record digests (every choice point's candidates, queries, answers, taken clip; every committed clip) and "
        "summary counters equal";
    t.notes["repeats"] = std::to_string(std::max(1, o.repeats)) + " rounds of runs (" + list +
                         " threads, in that order) per size, interleaved; times are medians";
    t.notes["memory"] =
        "peak resident size of the process during each size's runs (VmHWM, reset before each run); every run "
        "streams its decisions to a digest and its frames to the contact check, keeping no record";
    t.notes["large sizes"] = "from " + std::to_string(o.once_from) + " agents one round of runs; from " +
                             std::to_string(o.parallel_only_from) + " only the " + std::to_string(threads) +
                             "-thread run (the other counts' columns empty)";
    t.notes["hardware threads"] = std::to_string(util::WorkerPool::hardware_threads());
    if (progress) progress(1.0);
    return t;
}

}  // namespace mobb::bench
