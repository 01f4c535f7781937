// The scale workload (scale.h): the avoiding crowd at the paper's density, 1 and all threads.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <stdexcept>

#include "mobb/crowd/crowd.h"
#include "mobb/util/json_text.h"
#include "mobb/util/median.h"
#include "mobb/util/worker_pool.h"
#include "scale.h"
#include "workloads.h"

namespace mobb::bench {

using namespace crowd;  // the scale workload is a crowd run

namespace {

// 64-bit FNV-1a over integers and doubles (bit patterns).
struct Fnv {
    std::uint64_t h = 1469598103934665603ull;
    void add(std::uint64_t v) {
        for (int k = 0; k < 8; ++k) {
            h ^= (v >> (8 * k)) & 0xffu;
            h *= 1099511628211ull;
        }
    }
    void add(double v) {
        std::uint64_t bits = 0;
        static_assert(sizeof bits == sizeof v);
        std::memcpy(&bits, &v, sizeof v);
        add(bits);
    }
};

void hash_choice(Fnv& f, const ChoicePoint& cp) {
    f.add(std::uint64_t(cp.agent));
    f.add(std::uint64_t(cp.frame));
    f.add(std::uint64_t(cp.taken));
    f.add(std::uint64_t(cp.fallback));
    f.add(cp.queries);
    f.add(cp.pruned);
    for (const Candidate& c : cp.candidates) {
        f.add(std::uint64_t(c.clip));
        f.add(std::uint64_t(c.leaves_world || c.meets_solid));  // one bit, as bench/results/scale.json has it
        f.add(std::uint64_t(c.hits));
        for (const CandidateQuery& q : c.against)
            f.add((std::uint64_t(std::uint32_t(q.agent)) << 40) ^ (std::uint64_t(std::uint32_t(query_index(q))) << 8) ^
                  (std::uint64_t(q.piece + 1) << 1) ^ std::uint64_t(q.hit));
    }
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
    co.select = Selection::Avoid;
    return co;
}

CrowdRun run_one(const MotionGraph& g, const NarrowPhase& narrow, const ScaleOptions& o, int agents, int threads,
                 const std::function<void(double)>& progress) {
    CrowdOptions co = crowd_options(o, agents);
    co.threads = threads;
    return run_crowd(g, narrow, co, progress);
}

// Wall times of the runs of one size: [0] 1 thread, [1] `threads`; medians over the repeats.
struct Times {
    std::vector<double> sim[2], cd[2];
};

// One run; returns its summary and record digest, and adds its times.
CrowdSummary timed_run(const MotionGraph& g, const NarrowPhase& narrow, const ScaleOptions& o, int agents, int threads,
                       Times& times, int slot, std::string& digest, const std::function<void(double)>& progress) {
    const CrowdRun run = run_one(g, narrow, o, agents, threads, progress);
    times.sim[slot].push_back(run.summary.seconds);
    times.cd[slot].push_back(run.summary.cd_seconds);
    digest = record_digest(run.record);
    return run.summary;
}

// One crowd size: `repeats` pairs of runs (1 thread, then `threads`), interleaved; records compared by
// digest and counters; times are medians.
ScaleRow scale_row(const MotionGraph& g, const NarrowPhase& narrow, const ScaleOptions& o, int agents, int threads,
                   const std::function<void(double)>& progress) {
    ScaleRow r;
    r.agents = agents;
    r.threads = threads;
    world_for(agents, o.area_per_agent, r.width, r.height);
    Times times;
    CrowdSummary s1, sn;
    r.identical = true;
    const int repeats = std::max(1, o.repeats);
    for (int k = 0; k < repeats; ++k) {
        std::string d1, dn;
        const auto part = [&](int slot) {
            return [&, slot](double f) {
                if (progress) progress((2.0 * k + slot + f) / (2.0 * repeats));
            };
        };
        s1 = timed_run(g, narrow, o, agents, 1, times, 0, d1, part(0));
        sn = timed_run(g, narrow, o, agents, threads, times, 1, dn, part(1));
        if (k == 0) {
            r.digest_1 = d1;
            r.digest_n = dn;
        }
        r.identical = r.identical && d1 == r.digest_1 && dn == r.digest_n && d1 == dn && s1.queries == sn.queries &&
                      s1.hits == sn.hits && s1.contacts == sn.contacts && s1.choice_points == sn.choice_points &&
                      s1.fallbacks == sn.fallbacks;
    }
    r.choice_points = s1.choice_points;
    r.candidates = s1.candidates;
    r.queries = s1.queries;
    r.fallbacks = s1.fallbacks;
    r.contacts_unexcused = s1.contacts_unexcused;
    r.sim_seconds_1 = util::median(times.sim[0]);
    r.sim_seconds_n = util::median(times.sim[1]);
    r.cd_seconds_1 = util::median(times.cd[0]);
    r.cd_seconds_n = util::median(times.cd[1]);
    r.cd_us_per_agent_second = r.cd_seconds_1 * 1e6 / (double(agents) * o.seconds);
    r.cd_us_per_query = s1.queries ? r.cd_seconds_1 * 1e6 / double(s1.queries) : 0.0;
    const bool cd = r.cd_seconds_1 > 0 && r.cd_seconds_n > 0;
    r.speedup = cd ? r.cd_seconds_1 / r.cd_seconds_n : r.sim_seconds_n > 0 ? r.sim_seconds_1 / r.sim_seconds_n : 0.0;
    return r;
}

void add_scale_targets(ScaleTable& t) {
    const ScaleRow &first = t.rows.front(), &last = t.rows.back();
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
    t.targets.push_back(cost);
    Target contacts;
    contacts.what = "no contacts outside fallbacks (all sizes)";
    contacts.goal = 0;
    contacts.at_most = true;
    contacts.ratio = false;
    for (const ScaleRow& r : t.rows) contacts.measured += double(r.contacts_unexcused);
    contacts.detail = "frame-by-frame check of the 1-thread records";
    t.targets.push_back(contacts);
    Target speed;
    speed.what = "choice points on " + std::to_string(last.threads) + " threads >= 1.8x faster, records identical";
    speed.goal = 1.8;
    speed.measured = last.speedup;
    bool same = true;
    for (const ScaleRow& r : t.rows) same = same && r.identical;
    speed.detail = std::string(last.cd_seconds_n > 0 ? "CD" : "simulation") + " wall time at " +
                   std::to_string(last.agents) + " agents; records " +
                   (same ? "identical at every size" : "DIFFER at some size");
    if (!same) speed.measured = 0;
    t.targets.push_back(speed);
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

}  // namespace

std::string record_digest(const Record& r) {
    Fnv f;
    for (const ChoicePoint& cp : r.choices) hash_choice(f, cp);
    for (const AgentTrack& t : r.tracks)
        for (const PlacedClip& c : t.clips) {
            f.add(std::uint64_t(c.clip));
            f.add(std::uint64_t(c.start));
            f.add(c.place.x);
            f.add(c.place.y);
            f.add(c.place.theta);
            f.add(std::uint64_t(c.fallback));
            f.add(std::uint64_t(c.choice));
        }
    char buf[20];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(f.h));
    return buf;
}

ScaleTable run_scale(const ScaleOptions& o, const std::function<void(double)>& progress) {
    if (o.agents.empty()) throw std::invalid_argument("scale: no crowd sizes");
    const MotionGraph g = load_graph(o.graph);
    const NarrowPhase narrow = NarrowPhase::sweep(g);
    const int threads = o.threads > 0 ? o.threads : util::WorkerPool::hardware_threads();
    double total = 0, done = 0;
    for (int n : o.agents) total += double(n);
    ScaleTable t;
    for (int n : o.agents) {
        t.rows.push_back(scale_row(g, narrow, o, n, threads, [&](double f) {
            if (progress) progress((done + f * n) / total);
        }));
        done += double(n);
        if (!o.save_queries.empty()) save_scale_queries(g, narrow, o, n);
    }
    for (ScaleRow& r : t.rows)
        r.ratio_to_first = t.rows.front().cd_us_per_agent_second > 0
                               ? r.cd_us_per_agent_second / t.rows.front().cd_us_per_agent_second
                               : 0;
    add_scale_targets(t);
    t.title = "Scale: avoiding crowd at the paper's density (" + util::fixed(o.area_per_agent, 0) +
              " m^2 per agent), " + util::fixed(o.seconds, 0) + " s simulated, 1 and " + std::to_string(threads) +
              " threads";
    t.notes["graph"] = o.graph;
    t.notes["crowd"] =
        "mobb crowd --select avoid, seed " + std::to_string(o.seed) + ", world 3:4 growing with the agents";
    t.notes["CD time"] = "CrowdSummary::cd_seconds (broad + narrow phase wall time inside run_crowd)";
    t.notes["speed-up"] = "1-thread time / " + std::to_string(threads) +
                          "-thread time: CD seconds when measured, else simulation seconds";
    t.notes["identical"] =
        "record digests (every choice point's candidates, queries, answers, taken clip; every committed clip) and "
        "summary counters equal";
    t.notes["repeats"] = std::to_string(std::max(1, o.repeats)) + " pairs of runs (1 thread, then " +
                         std::to_string(threads) + ") per size, interleaved; times are medians";
    t.notes["hardware threads"] = std::to_string(util::WorkerPool::hardware_threads());
    if (progress) progress(1.0);
    return t;
}

}  // namespace mobb::bench
