#include "crowd_workload.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
#include <stdexcept>

#include "mobb/crowd/crowd.h"
#include "mobb/crowd/motion_graph.h"
#include "mobb/crowd/query_methods.h"
#include "mobb/io/load.h"

namespace mobb::bench {

namespace {

constexpr double kPi = 3.141592653589793;
constexpr double kRootShare = 0.813;  // the crowd's share of MOBB root overlaps (bench/results/table1.md)

std::string graph_file() { return std::string(MOBB_BENCH_SOURCE_DIR) + "/assets/graphs/cmu_locomotion.json"; }

void centre(const Path& p, double& x, double& y) {
    x = y = 0;
    for (const Sample& s : p.samples) x += s.x, y += s.y;
    x /= double(p.size()), y /= double(p.size());
}

// As run_table2's random tests: b rotated at random, its centre uniform in a disk of radius R about
// a's centre, time offset uniform over the offsets where the two overlap.
std::vector<ClipQuery> random_tests(const std::vector<Path>& clips, double radius, int count, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<ClipQuery> out;
    const auto n = clips.size();
    for (int k = 0; k < count; ++k) {
        ClipQuery q;
        q.a = int(rng() % n), q.b = int(rng() % n);
        const Path &a = clips[std::size_t(q.a)], &b = clips[std::size_t(q.b)];
        const double theta = kPi * (2 * u(rng) - 1);
        const double rr = radius * std::sqrt(u(rng)), phi = kPi * (2 * u(rng) - 1);
        double cax, cay, cbx, cby;
        centre(a, cax, cay), centre(b, cbx, cby);
        const double c = std::cos(theta), s = std::sin(theta);
        q.pb.theta = theta;
        q.pb.x = cax + rr * std::cos(phi) - (c * cbx - s * cby);
        q.pb.y = cay + rr * std::sin(phi) - (s * cbx + c * cby);
        q.pb.t0 = -b.duration() + (a.duration() + b.duration()) * u(rng);
        out.push_back(q);
    }
    return out;
}

double root_share(const ClipWorkload& w, const std::vector<ClipQuery>& qs) {
    std::size_t n = 0;
    for (const ClipQuery& q : qs)
        n += crowd::roots_overlap(w.mobb1[std::size_t(q.a)], q.pa, w.mobb1[std::size_t(q.b)], q.pb);
    return double(n) / double(std::max<std::size_t>(1, qs.size()));
}

void prepare(ClipWorkload& w) {
    for (const Path& p : w.paths) {
        w.index.push_back(ClipIndex::build(p));
        w.mobb1.push_back(Tree::build(p, {TreeType::Mobb1, 10}));
        w.mobb.push_back(Tree::build(p, {TreeType::Mobb, 10}));
    }
}

void add_random_tests(ClipWorkload& w, int tests) {
    double lo = 0, hi = 100;
    for (int it = 0; it < 24; ++it) {
        const double mid = 0.5 * (lo + hi);
        (root_share(w, random_tests(w.paths, mid, 3000, 11)) > kRootShare ? lo : hi) = mid;
    }
    const double radius = 0.5 * (lo + hi);
    w.queries = random_tests(w.paths, radius, tests, 1);
    w.description += ", radius " + std::to_string(radius) + " m, root overlap " + std::to_string(root_share(w, w.queries));
}

}  // namespace

const char* to_string(CrowdMethod m) {
    switch (m) {
        case CrowdMethod::Fast: return "fast";
        case CrowdMethod::Scan: return "scan";
        case CrowdMethod::Mobb1: return "mobb1";
        case CrowdMethod::Mobb: return "mobb";
    }
    return "?";
}

CrowdMethod parse_crowd_method(const std::string& name) {
    for (int m = 0; m < kCrowdMethods; ++m)
        if (name == to_string(CrowdMethod(m))) return CrowdMethod(m);
    throw std::invalid_argument("unknown method " + name + " (fast, scan, mobb1, mobb)");
}

ClipWorkload ClipWorkload::make(const std::string& name, int tests) {
    ClipWorkload w;
    w.name = name;
    if (io::data_dir().empty()) throw std::runtime_error("no mocap data folder (set MOBB_DATA)");
    if (name == "crowd") {
        const crowd::MotionGraph g = crowd::load_graph(graph_file());
        crowd::CrowdOptions co;
        co.agents = 100, co.width = 30, co.height = 40, co.seconds = 60, co.seed = 1;
        co.select = crowd::Selection::Random;
        co.log_queries = true;
        const std::vector<Tree> trees = crowd::build_trees(g, {});
        const crowd::CrowdRun run = crowd::run_crowd(g, trees, co);
        for (const crowd::GraphClip& c : g.clips) w.paths.push_back(c.path);
        for (const crowd::LoggedQuery& q : run.queries) w.queries.push_back({q.clip_a, q.clip_b, q.pa, q.pb});
        prepare(w);
        w.description = "crowd 100 agents 30x40 m 60 s random selection, " + std::to_string(w.queries.size()) + " queries";
        return w;
    }
    if (name == "longest") {
        std::vector<std::string> files;
        for (const auto& e : std::filesystem::directory_iterator(io::data_dir() + "/cmu"))
            if (e.path().extension() == ".bvh") files.push_back(e.path().string());
        std::sort(files.begin(), files.end());
        io::LoadOptions lo;
        lo.fps = 30;
        for (const std::string& f : files) w.paths.push_back(io::load_clip(f, lo).path);
        std::stable_sort(w.paths.begin(), w.paths.end(), [](const Path& a, const Path& b) { return a.size() > b.size(); });
        if (w.paths.size() > 14) w.paths.resize(14);
        w.description = "14 longest CMU clips at 30 Hz";
    } else if (name == "synth42" || name == "synth120") {
        const double seconds = name == "synth42" ? 42 : 120;
        const crowd::MotionGraph g = crowd::load_graph(graph_file());
        std::mt19937_64 rng(5);
        for (int k = 0; k < 14; ++k) {
            Path p;
            p.dt = g.dt();
            int clip = int(rng() % g.clips.size());
            Placement at;
            while (p.duration() < seconds) {
                const Rigid2 m = Rigid2::of(at);
                for (const Sample& s : g.clips[std::size_t(clip)].path.samples)
                    p.samples.push_back({m.apply_x(s.x, s.y), m.apply_y(s.x, s.y), s.r});
                at = g.next(at, clip);
                const auto& succ = g.clips[std::size_t(clip)].successors;
                clip = succ[rng() % succ.size()];
            }
            w.paths.push_back(std::move(p));
        }
        w.description = "14 motion-graph walks of " + std::to_string(int(seconds)) + " s at 30 Hz";
    } else {
        throw std::invalid_argument("unknown workload " + name + " (crowd, longest, synth42, synth120)");
    }
    prepare(w);
    add_random_tests(w, tests);
    return w;
}

}  // namespace mobb::bench
