// Micro-benchmarks: what one box test, one leaf test and one scan cost, and whole queries per method
// side by side on the benchmark library's workloads (src/bench): the same methods and queries as
// `mobb bench`. Run with --benchmark_enable_random_interleaving=true and compare ratios within a run.
#include <benchmark/benchmark.h>

#include <cmath>
#include <map>
#include <memory>
#include <random>

#include "method.h"
#include "mobb/core/fit.h"
#include "mobb/crowd/collision/narrow_phase.h"
#include "mobb/crowd/motion/agent_pose.h"
#include "mobb/crowd/sim/crowd.h"
#include "mobb/core/query.h"
#include "mobb/core/scan.h"
#include "mobb/core/sweep.h"
#include "tables.h"
#include "workloads.h"

namespace {

using namespace mobb;

// The long-clip workload at `fps` (two ~42 s sequences, 4096 placements), built once per rate.
const bench::QuerySet& sequences(int fps) {
    static std::map<int, bench::QuerySet> cache;
    auto it = cache.find(fps);
    if (it == cache.end()) it = cache.emplace(fps, bench::sequence42_set(fps)).first;
    return it->second;
}

void Sat2D(benchmark::State& state) {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<Obb2> boxes(256);
    for (Obb2& b : boxes)
        b = {{2 * u(rng), 2 * u(rng)}, {std::cos(u(rng) * 6), std::sin(u(rng) * 6)}, {u(rng), u(rng)}};
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(overlap(boxes[i & 255], boxes[(i * 7 + 1) & 255]));
        ++i;
    }
}
BENCHMARK(Sat2D);

void Sat3D(benchmark::State& state) {
    const Path& p = sequences(60).clips[0];
    std::vector<Obb3> boxes;
    for (std::size_t f = 0; f + 20 < p.size(); f += 5) {
        Obb3 b;
        if (fit_obb3(p, f, f + 20, b)) boxes.push_back(b);
    }
    std::size_t i = 0;
    const std::size_t n = boxes.size();
    for (auto _ : state) {
        benchmark::DoNotOptimize(overlap(boxes[i % n], boxes[(i * 7 + 3) % n]));
        ++i;
    }
}
BENCHMARK(Sat3D);

void LeafTest(benchmark::State& state) {
    const Path& p = sequences(60).clips[0];
    const Placement pa{0, 0, 0, 0}, pb{50, 0, 0, 0.004};  // far apart: every aligned pair is tested
    const Rigid2 ta = Rigid2::of(pa), tb = Rigid2::of(pb);
    const auto n = std::int64_t(state.range(0));
    for (auto _ : state) {
        std::uint64_t tested = 0;
        SamplePair hit;
        benchmark::DoNotOptimize(leaf_test(p, pa, ta, 100, 100 + n, p, pb, tb, 100, 100 + n, tested, hit));
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(LeafTest)->Arg(10)->Arg(1000);

// A wavy walk and its copy 0.7 m to the side, radii 0.3 m: the root boxes overlap but no pair
// collides, so every time-aligned pair is filtered (scan) or every circle tested (sweep).
struct WavyPair {
    ClipIndex a, b;
    static WavyPair make(int n) {
        Path p;
        for (int i = 0; i < n; ++i) p.samples.push_back({0.02 * i, std::sin(0.02 * i), 0.3});
        return {ClipIndex::build(p), ClipIndex::build(p)};
    }
};

template <bool kSweep>
void ScanNoHit(benchmark::State& state) {
    const WavyPair w = WavyPair::make(int(state.range(0)));
    const Placement pa{0, 0, 0, 0}, pb{0, 0.7, 0, 0.25 / 60};
    for (auto _ : state)
        benchmark::DoNotOptimize(kSweep ? collide_sweep(w.a, pa, w.b, pb) : collide_scan(w.a, pa, w.b, pb));
    state.SetItemsProcessed(state.iterations() * 2 * state.range(0));  // time-aligned pairs
}
BENCHMARK(ScanNoHit<false>)->Arg(64)->Arg(2520);
BENCHMARK(ScanNoHit<true>)->Arg(64)->Arg(2520);

// Cycles one method over a workload's queries; "positive" is the share of hits, "agree" the share of
// answers equal to the circle sweep's (exact, held to brute force by the tests): FCL's mesh may differ.
void run_queries(benchmark::State& state, const bench::QuerySet& set, bench::Method m) {
    const auto method = bench::make_method(m);
    if (!method->unavailable().empty()) {
        state.SkipWithError(method->unavailable().c_str());
        return;
    }
    method->prepare(set.clips);
    const auto exact = bench::make_method(bench::Method::Sweep);
    exact->prepare(set.clips);
    const std::size_t n = set.queries.size();
    std::vector<char> expected(n);
    for (std::size_t k = 0; k < n; ++k) {
        const bench::ClipQuery& q = set.queries[k];
        expected[k] = exact->query(q.a, q.pa, q.b, q.pb, nullptr);
    }
    std::size_t i = 0, hits = 0, agree = 0, count = 0;
    for (auto _ : state) {
        const bench::ClipQuery& q = set.queries[i];
        const bool hit = method->query(q.a, q.pa, q.b, q.pb, nullptr);
        hits += hit;
        agree += hit == bool(expected[i]);
        ++count;
        if (++i == n) i = 0;
    }
    state.SetLabel(bench::label(m));
    state.counters["positive"] = double(hits) / double(count);
    state.counters["agree"] = double(agree) / double(count);
}

// Whole queries on the two ~42 s sequences: args (method, fps).
void Seq42(benchmark::State& state) {
    run_queries(state, sequences(int(state.range(1))), bench::Method(state.range(0)));
}
BENCHMARK(Seq42)->ArgsProduct({benchmark::CreateDenseRange(0, bench::kMethodCount - 1, 1), {30, 60}});

// `mobb bench`'s workloads side by side: args (workload, method). Workloads: 0 table1 (the crowd's
// queries), 1 table2 (the longest clips), 2 synth42, 3 synth120 (motion-graph walks). Methods: the
// circle sweep, the best scan, the paper's 1 level and MOBB.
const char* const kWorkloads[] = {"table1", "table2", "synth42", "synth120"};
constexpr bench::Method kWorkloadMethods[] = {bench::Method::Sweep, bench::Method::Scan, bench::Method::Mobb1,
                                              bench::Method::Mobb};

void Workload(benchmark::State& state) {
    static std::map<int, bench::QuerySet> cache;
    const int which = int(state.range(0));
    auto it = cache.find(which);
    if (it == cache.end()) {
        try {
            it = cache.emplace(which, bench::named_query_set(kWorkloads[which], MOBB_GRAPH)).first;
        } catch (const std::exception& e) {
            state.SkipWithError(e.what());
            return;
        }
    }
    run_queries(state, it->second, kWorkloadMethods[state.range(1)]);
    state.SetLabel(std::string(kWorkloads[which]) + " " + bench::label(kWorkloadMethods[state.range(1)]));
}
BENCHMARK(Workload)->ArgsProduct({{0, 1, 2, 3}, {0, 1, 2, 3}});

}  // namespace

// Posing a crowd (CrowdPoser: every agent at every frame, all joints, blended) with foot locking off (0)
// and on (1): a 20 s wander of 100 agents in 30 x 40 m, or 1,000 in 94.9 x 126.5 m (the same density),
// seed 1, run once. Needs the graph's motion capture (skipped without it).
struct PosingCrowd {
    std::shared_ptr<crowd::MotionGraph> graph;
    crowd::Record record;
};
const PosingCrowd& posing_crowd(int agents) {
    static std::map<int, PosingCrowd> cache;
    auto it = cache.find(agents);
    if (it != cache.end()) return it->second;
    PosingCrowd c{std::make_shared<crowd::MotionGraph>(crowd::load_graph(MOBB_GRAPH)), {}};
    crowd::CrowdOptions o;
    o.agents = agents;
    o.world.x1 = agents > 100 ? 94.9 : 30;
    o.world.y1 = agents > 100 ? 126.5 : 40;
    o.seconds = 20;
    o.seed = 1;
    o.record_queries = false;
    c.record = crowd::run_crowd(*c.graph, crowd::NarrowPhase::sweep(*c.graph), o).record;
    return cache.emplace(agents, std::move(c)).first->second;
}

void CrowdPosing(benchmark::State& state) {
    const PosingCrowd& c = posing_crowd(int(state.range(0)));
    crowd::FootLock lock;
    lock.on = state.range(1) != 0;
    std::unique_ptr<crowd::CrowdPoser> poser;
    try {
        poser = std::make_unique<crowd::CrowdPoser>(c.record, std::make_shared<crowd::PoseSources>(c.graph),
                                                    crowd::RigJoints::All, crowd::PoseBlend{}, lock);
    } catch (const std::exception& e) {
        state.SkipWithError(e.what());
        return;
    }
    std::vector<glm::dvec3> pose;
    for (auto _ : state)
        for (int a = 0; a < int(c.record.tracks.size()); ++a)
            for (std::int64_t k = 0; k < c.record.frames; ++k) {
                poser->pose(a, k, pose);
                benchmark::DoNotOptimize(pose.data());
            }
    state.SetItemsProcessed(state.iterations() * std::int64_t(c.record.tracks.size()) * c.record.frames);
}
BENCHMARK(CrowdPosing)->ArgsProduct({{100, 1000}, {0, 1}})->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
