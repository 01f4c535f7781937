// Micro-benchmarks of the core: what one box test, one leaf test, one scan and one whole query cost,
// per method side by side (paper trees, brute force, best scan, fast query, FCL) on ~42 s sequences.
// Queries use real clips when the mocap folder is present, random walks otherwise (reported).
#include <benchmark/benchmark.h>

#include <cmath>
#include <map>
#include <random>

#include "mobb/core/brute.h"
#include "mobb/core/fast_query.h"
#include "mobb/core/query.h"
#include "mobb/core/scan.h"
#include "mobb/io/load.h"
#include "crowd_workload.h"
#include "workload.h"

namespace {

using namespace mobb;

Path walk(std::mt19937_64& rng, int n) {
    std::uniform_real_distribution<double> u(0, 1);
    Path p;
    double x = 0, y = 0, h = 0;
    for (int i = 0; i < n; ++i) {
        h += 0.05 * (u(rng) - 0.5);
        x += 0.02 * std::cos(h), y += 0.02 * std::sin(h);
        p.samples.push_back({x, y, 0.3 + 0.1 * u(rng)});
    }
    return p;
}

// A long real clip (001_01, 22.9 s) or a random walk of the same length.
const Path& long_path() {
    static const Path p = [] {
        const std::string dir = io::data_dir();
        if (!dir.empty()) {
            try {
                return io::load_clip(dir + "/cmu/001_01.bvh").path;
            } catch (const std::exception&) {
            }
        }
        std::mt19937_64 rng(1);
        return walk(rng, 1376);
    }();
    return p;
}

struct Placements {
    std::vector<Placement> a, b;
};

// Random translation, rotation and time offset around the clip, as in the paper's Table 2 setup.
const Placements& placements() {
    static const Placements p = [] {
        Placements out;
        std::mt19937_64 rng(2);
        std::uniform_real_distribution<double> u(0, 1);
        const double d = long_path().duration();
        for (int i = 0; i < 4096; ++i) {
            out.a.push_back({0, 0, 0, 0});
            out.b.push_back({8 * (u(rng) - 0.5), 8 * (u(rng) - 0.5), 6.2831853 * u(rng), d * (u(rng) - 0.5)});
        }
        return out;
    }();
    return p;
}

void Sat2D(benchmark::State& state) {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<Obb2> boxes(256);
    for (Obb2& b : boxes) b = {{2 * u(rng), 2 * u(rng)}, {std::cos(u(rng) * 6), std::sin(u(rng) * 6)}, {u(rng), u(rng)}};
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(overlap(boxes[i & 255], boxes[(i * 7 + 1) & 255]));
        ++i;
    }
}
BENCHMARK(Sat2D);

void Sat3D(benchmark::State& state) {
    const Path& p = long_path();
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
    const Path& p = long_path();
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

void Query(benchmark::State& state) {
    const auto type = TreeType(state.range(0));
    const Tree tree = Tree::build(long_path(), {type, 10});
    const Placements& p = placements();
    std::size_t i = 0, hits = 0;
    for (auto _ : state) {
        hits += collide(tree, p.a[i & 4095], tree, p.b[i & 4095]);
        ++i;
    }
    state.SetLabel(std::string(to_string(type)) + (io::data_dir().empty() ? " (random walk)" : " (001_01)"));
    state.counters["positive"] = double(hits) / double(i);
}
BENCHMARK(Query)->DenseRange(0, 5);

void QueryBrute(benchmark::State& state) {
    const Path& path = long_path();
    const Placements& p = placements();
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(collide_brute(path, p.a[i & 4095], path, p.b[i & 4095]));
        ++i;
    }
}
BENCHMARK(QueryBrute);

// A wavy walk and its copy 0.7 m to the side, radii 0.3 m: the root boxes overlap but no pair
// collides, so every time-aligned pair is filtered (scan) or every circle tested (fast query).
struct WavyPair {
    ClipIndex a, b;
    static WavyPair make(int n) {
        Path p;
        for (int i = 0; i < n; ++i) p.samples.push_back({0.02 * i, std::sin(0.02 * i), 0.3});
        return {ClipIndex::build(p), ClipIndex::build(p)};
    }
};

template <bool kFast>
void ScanNoHit(benchmark::State& state) {
    const WavyPair w = WavyPair::make(int(state.range(0)));
    const Placement pa{0, 0, 0, 0}, pb{0, 0.7, 0, 0.25 / 60};
    for (auto _ : state) benchmark::DoNotOptimize(kFast ? collide_fast(w.a, pa, w.b, pb) : collide_scan(w.a, pa, w.b, pb));
    state.SetItemsProcessed(state.iterations() * 2 * state.range(0));  // time-aligned pairs
}
BENCHMARK(ScanNoHit<false>)->Arg(64)->Arg(2520);
BENCHMARK(ScanNoHit<true>)->Arg(64)->Arg(2520);

// Whole queries on two ~42 s real sequences (bench/sequences.h) under 4096 random placements:
// args (method, fps). "agree" is the share of answers equal to the exact ones (fast query, checked
// against brute force in the tests): 1 for every exact method, FCL's conservative mesh may differ.
const bench::Workload& workload(int fps) {
    static std::map<int, bench::Workload> cache;
    auto it = cache.find(fps);
    if (it == cache.end()) it = cache.emplace(fps, bench::Workload::make(fps, true)).first;
    return it->second;
}

void Seq42(benchmark::State& state) {
    const auto m = bench::Method(state.range(0));
    const bench::Workload& w = workload(int(state.range(1)));
    if (m == bench::Method::Fcl && w.fcl.empty()) {
        state.SkipWithError("built without FCL (install libfcl-dev)");
        return;
    }
    const std::size_t n = w.size();
    std::vector<char> exact(n);
    for (std::size_t i = 0; i < n; ++i) exact[i] = w.query(bench::Method::Fast, i);
    std::size_t i = 0, hits = 0, agree = 0, count = 0;
    for (auto _ : state) {
        const bool hit = w.query(m, i);
        hits += hit;
        agree += hit == bool(exact[i]);
        ++count;
        if (++i == n) i = 0;
    }
    state.SetLabel(std::string(bench::to_string(m)) + " " + bench::source() + " " + std::to_string(state.range(1)) + " Hz");
    state.counters["positive"] = double(hits) / double(count);
    state.counters["agree"] = double(agree) / double(count);
}
BENCHMARK(Seq42)->ArgsProduct({benchmark::CreateDenseRange(0, bench::kMethods - 1, 1), {30, 60}});

// Issue 5's workloads (bench/crowd_workload.h) side by side: args (workload, method). Workloads:
// 0 crowd (the crowd's logged queries, Table 1 like), 1 longest (14 longest CMU clips, Table 2 like),
// 2 synth42, 3 synth120 (motion-graph walks). Methods: 0 fast, 1 scan, 2 mobb1 (paper 1-level),
// 3 mobb. Run with --benchmark_enable_random_interleaving=true and compare ratios.
const bench::ClipWorkload& clip_workload(int which) {
    static const char* names[] = {"crowd", "longest", "synth42", "synth120"};
    static std::map<int, bench::ClipWorkload> cache;
    auto it = cache.find(which);
    if (it == cache.end()) it = cache.emplace(which, bench::ClipWorkload::make(names[which])).first;
    return it->second;
}

void Issue5(benchmark::State& state) {
    const bench::ClipWorkload* w = nullptr;
    try {
        w = &clip_workload(int(state.range(0)));
    } catch (const std::exception& e) {
        state.SkipWithError(e.what());
        return;
    }
    const auto m = bench::CrowdMethod(state.range(1));
    const std::size_t n = w->size();
    std::size_t i = 0, hits = 0, count = 0;
    for (auto _ : state) {
        hits += w->query(m, i);
        ++count;
        if (++i == n) i = 0;
    }
    state.SetLabel(w->name + " " + bench::to_string(m));
    state.counters["positive"] = double(hits) / double(count);
}
BENCHMARK(Issue5)->ArgsProduct({{0, 1, 2, 3}, {0, 1, 2, 3}});

}  // namespace

BENCHMARK_MAIN();
