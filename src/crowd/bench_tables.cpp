#include "mobb/crowd/bench_tables.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "bar_chart.h"
#include "json_text.h"
#include "mobb/crowd/crowd.h"
#include "mobb/crowd/frame_stepping.h"
#include "mobb/io/load.h"
#include "random.h"

namespace mobb::crowd {

namespace {

using Clock = std::chrono::steady_clock;
constexpr double kPi = 3.14159265358979323846;

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// Maps [0, 1] of a stage onto [lo, hi] of the whole run.
std::function<void(double)> stage(const std::function<void(double)>& p, double lo, double hi) {
    if (!p) return {};
    return [p, lo, hi](double f) { p(lo + (hi - lo) * std::clamp(f, 0.0, 1.0)); };
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n == 0 ? 0.0 : n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::string cpu_name() {
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
    return "unknown";
}

void add_machine_notes(BenchTable& t) {
    t.notes["cpu"] = cpu_name();
    t.notes["timing"] = "median over timed passes of (pass time / queries); methods interleaved within each pass";
}

double root_share(const std::vector<Tree>& trees, const std::vector<BenchQuery>& qs) {
    std::uint64_t roots = 0;
    for (const BenchQuery& q : qs)
        if (roots_overlap(trees[std::size_t(q.a)], q.pa, trees[std::size_t(q.b)], q.pb)) ++roots;
    return qs.empty() ? 0.0 : double(roots) / double(qs.size());
}

std::vector<Tree> mobb_trees(const std::vector<Path>& clips, int n_min) {
    std::vector<Tree> out;
    TreeOptions o;
    o.n_min = n_min;
    for (const Path& p : clips) out.push_back(Tree::build(p, o));
    return out;
}

}  // namespace

namespace {

// The untimed pass of one method: answers (the first `count` queries), tests, positives.
MethodRow count_pass(const QuerySet& set, const QueryMethod& m, std::size_t count, std::vector<bool>& answers) {
    QueryStats st;
    std::uint64_t pos = 0;
    for (std::size_t k = 0; k < count; ++k) {
        const BenchQuery& q = set.queries[k];
        const bool hit = m.query(q.a, q.pa, q.b, q.pb, &st);
        answers.push_back(hit);
        pos += hit;
    }
    MethodRow r;
    r.method = m.name();
    r.queries = count;
    const double d = double(std::max<std::size_t>(1, count));
    r.tests2d = double(st.tests2d) / d;
    r.tests3d = double(st.tests3d) / d;
    r.samples = double(st.samples) / d;
    r.positive = double(pos) / d;
    r.note = m.note();
    return r;
}

// One timed pass of one method over the first `count` queries: microseconds per query.
double timed_pass(const QuerySet& set, const QueryMethod& m, std::size_t count) {
    static volatile bool sink = false;
    const auto t0 = Clock::now();
    bool acc = false;
    for (std::size_t k = 0; k < count; ++k) {
        const BenchQuery& q = set.queries[k];
        acc ^= m.query(q.a, q.pa, q.b, q.pb, nullptr);
    }
    const double us = seconds_since(t0) * 1e6 / double(std::max<std::size_t>(1, count));
    sink = sink ^ acc;
    return us;
}

// Disagreements with the brute-force row (over the queries both answered) and ratios to the mobb row.
void compare_rows(std::vector<MethodRow>& rows, const std::vector<std::vector<bool>>& answers) {
    std::size_t ref = rows.size(), fast = rows.size();
    for (std::size_t m = 0; m < rows.size(); ++m) {
        if (rows[m].method == "brute force") ref = m;
        if (rows[m].method == "mobb" && rows[m].measured) fast = m;
    }
    for (std::size_t m = 0; m < rows.size(); ++m) {
        if (ref < rows.size()) {
            const std::size_t n = std::min(answers[m].size(), answers[ref].size());
            for (std::size_t k = 0; k < n; ++k) {
                rows[m].extra += answers[m][k] && !answers[ref][k];
                rows[m].missed += !answers[m][k] && answers[ref][k];
            }
            rows[m].disagreements = rows[m].extra + rows[m].missed;
        }
        if (fast < rows.size() && rows[fast].us_per_query > 0 && rows[m].measured)
            rows[m].x_mobb = rows[m].us_per_query / rows[fast].us_per_query;
    }
}

}  // namespace

std::vector<MethodRow> time_methods(const QuerySet& set, const std::vector<std::unique_ptr<QueryMethod>>& methods,
                                    int passes, const std::function<void(double)>& progress, std::size_t slow_queries) {
    const std::size_t n = set.queries.size(), nm = methods.size();
    std::vector<MethodRow> rows(nm);
    std::vector<std::vector<bool>> answers(nm);
    std::vector<std::size_t> timed(nm, 0);
    for (std::size_t m = 0; m < nm; ++m) {
        const QueryMethod& qm = *methods[m];
        if (!qm.unavailable().empty()) {
            rows[m].method = qm.name();
            rows[m].measured = false;
            rows[m].note = qm.unavailable();
            continue;
        }
        methods[m]->prepare(set.clips);
        timed[m] = qm.slow() ? std::min(n, slow_queries) : n;
        const bool reference = qm.name() == "brute force";
        rows[m] = count_pass(set, qm, reference ? n : timed[m], answers[m]);
        rows[m].timed_queries = timed[m];
        if (timed[m] < n) rows[m].note += std::string(rows[m].note.empty() ? "" : "; ") + "timed on the first " +
                                          std::to_string(timed[m]) + " queries";
        if (progress) progress(0.2 * double(m + 1) / double(nm));
    }
    std::vector<std::vector<double>> times(nm);
    for (int p = 0; p < passes; ++p)
        for (std::size_t m = 0; m < nm; ++m) {
            if (rows[m].measured) times[m].push_back(timed_pass(set, *methods[m], timed[m]));
            if (progress) progress(0.2 + 0.8 * double(std::size_t(p) * nm + m + 1) / double(std::size_t(passes) * nm));
        }
    for (std::size_t m = 0; m < nm; ++m) rows[m].us_per_query = median(times[m]);
    compare_rows(rows, answers);
    return rows;
}

namespace {

const MethodRow* find_row(const BenchTable& t, const std::string& method) {
    for (const MethodRow& r : t.rows)
        if (r.method == method && r.measured && r.us_per_query > 0) return &r;
    return nullptr;
}

// Target "mobb >= goal x faster than <peer>" from the table's rows.
Target speed_target(const BenchTable& t, const std::string& peer, double goal) {
    Target g;
    g.what = "mobb >= " + fixed(goal, 0) + "x faster than " + peer;
    g.goal = goal;
    const MethodRow *m = find_row(t, "mobb"), *p = find_row(t, peer);
    if (!m || !p) {
        g.known = false;
        g.detail = "no measured " + std::string(m ? peer : "mobb") + " row";
        return g;
    }
    g.measured = p->us_per_query / m->us_per_query;
    g.detail = fixed(p->us_per_query, 3) + " us / " + fixed(m->us_per_query, 3) + " us per query";
    return g;
}

}  // namespace

namespace {

// Issue 5's Table 1 targets; the crowd-against-frame-stepping one is per simulated second, on the
// choice points of this run (the crowd's own CD time, CrowdSummary::cd_seconds).
void add_table1_targets(BenchTable& t, const CrowdSummary& s, const FrameSteppingResult& fs, double seconds) {
    t.targets.push_back(speed_target(t, "best scan", 1));
    t.targets.push_back(speed_target(t, "MOBB 1 level", 4));
    Target g;
    g.what = "crowd CD time per simulated second >= 10x less than frame stepping on the same choice points";
    g.goal = 10;
    const double step = (fs.build_seconds + fs.check_seconds) / seconds;
    const MethodRow* m = find_row(t, "mobb");
    const double replay = m ? m->us_per_query * 1e-6 * double(m->queries) / seconds : 0;
    g.detail = "frame stepping " + fixed(step * 1e3, 3) + " ms per simulated s; crowd cd_seconds " +
               fixed(s.cd_seconds / seconds * 1e3, 3) + " ms per simulated s; mobb replay of the same queries " +
               fixed(replay * 1e3, 3) + " ms per simulated s (narrow phase only, " + fixed(replay > 0 ? step / replay : 0, 1) + "x)";
    if (s.cd_seconds > 0) {
        g.measured = step / (s.cd_seconds / seconds);
    } else {
        g.known = false;
        g.detail = "CrowdSummary::cd_seconds reads 0 (not measured by run_crowd yet); " + g.detail;
    }
    t.targets.push_back(g);
}

}  // namespace

BenchTable run_table1(const Table1Options& o, std::vector<std::unique_ptr<QueryMethod>> extra,
                      const std::function<void(double)>& progress) {
    const MotionGraph g = load_graph(o.graph);
    CrowdOptions co;
    co.agents = o.agents;
    co.width = o.width;
    co.height = o.height;
    co.seconds = o.seconds;
    co.seed = o.seed;
    co.select = Selection::Random;
    co.log_queries = true;
    TreeOptions to;
    to.n_min = o.n_min;
    const std::vector<Tree> trees = build_trees(g, to);
    const CrowdRun run = run_crowd(g, trees, co, stage(progress, 0.0, 0.1));

    QuerySet set;
    for (const GraphClip& c : g.clips) set.clips.push_back(c.path);
    for (const LoggedQuery& q : run.queries) set.queries.push_back({q.clip_a, q.clip_b, q.pa, q.pb});
    if (!o.save_queries.empty()) save_query_set(set, o.save_queries);
    std::vector<std::unique_ptr<QueryMethod>> methods = bench_methods(o.n_min);
    for (auto& m : extra) methods.push_back(std::move(m));

    BenchTable t;
    t.workload = "table1";
    t.title = "Table 1: crowd workload (" + std::to_string(o.agents) + " agents, " + fixed(o.width, 0) + " x " +
              fixed(o.height, 0) + " m, " + fixed(o.seconds, 0) + " s, random selection)";
    t.rows = time_methods(set, methods, o.passes, stage(progress, 0.1, 0.95), o.slow_queries);

    const FrameSteppingResult fs = frame_stepping(g, run.record);
    MethodRow step;
    step.method = "frame stepping";
    step.queries = set.queries.size();
    const double nq = double(std::max<std::size_t>(1, set.queries.size()));
    step.us_per_query = (fs.build_seconds + fs.check_seconds) * 1e6 / nq;
    step.samples = double(fs.disk_tests) / nq;
    step.positive = fs.candidates ? double(fs.positive) / double(fs.candidates) : 0.0;
    step.disagreements = fs.disagreements;
    step.extra = fs.only_stepping;
    step.missed = fs.only_queries;
    step.note = "per candidate, not per query; time = (grid build + stepping) / queries";
    step.timed_queries = step.queries;
    if (const MethodRow* m = find_row(t, "mobb")) step.x_mobb = step.us_per_query / m->us_per_query;
    t.rows.push_back(step);
    if (progress) progress(1.0);

    double clip_seconds = 0;
    for (const GraphClip& c : g.clips) clip_seconds += c.path.duration();
    const CrowdSummary& s = run.summary;
    t.notes["graph"] = o.graph + " (" + std::to_string(g.clips.size()) + " clips, mean " +
                       fixed(clip_seconds / double(g.clips.size()), 2) + " s, dt 1/" + fixed(g.fps, 0) + " s)";
    t.notes["crowd"] = std::to_string(o.agents) + " agents, " + fixed(o.width, 0) + " x " + fixed(o.height, 0) + " m, " +
                       fixed(o.seconds, 0) + " s, seed " + std::to_string(o.seed) + ", random selection, n_min " +
                       std::to_string(o.n_min);
    t.notes["choice points"] = std::to_string(s.choice_points) + " (" + std::to_string(s.candidates) + " candidates)";
    t.notes["queries"] = std::to_string(set.queries.size()) + " (every row answers these same queries)";
    t.notes["rejected at the root (MOBB)"] = fixed(100.0 * double(s.root_rejected) / nq, 1) + " %";
    t.notes["root overlap share (MOBB root boxes)"] = fixed(100.0 * root_share(trees, set.queries), 1) + " %";
    t.notes["broad phase"] = std::to_string(s.pruned) + " of " + std::to_string(s.time_pairs) +
                             " time-overlapping pairs pruned before any query";
    t.notes["frame stepping"] = std::to_string(fs.candidates) + " candidates, grid build " + fixed(fs.build_seconds * 1e3, 2) +
                                " ms, stepping " + fixed(fs.check_seconds * 1e3, 2) + " ms, " + std::to_string(fs.disk_tests) +
                                " disk tests, " + std::to_string(fs.disagreements) + " answers differing from the queries' (" +
                                std::to_string(fs.only_queries) + " positive by the queries only, " +
                                std::to_string(fs.only_stepping) + " by stepping only)";
    t.notes["crowd simulation (MOBB queries, broad phase, bookkeeping)"] =
        fixed(s.seconds * 1e3, 1) + " ms, " + fixed(s.seconds * 1e6 / double(std::max<std::uint64_t>(1, s.choice_points)), 2) +
        " us per choice point";
    add_table1_targets(t, run.summary, fs, o.seconds);
    t.notes["tree time per choice point (MOBB)"] = fixed(t.rows[2].us_per_query * nq / double(std::max<std::uint64_t>(1, s.choice_points)), 2) + " us";
    t.notes["frame stepping time per choice point"] = fixed((fs.build_seconds + fs.check_seconds) * 1e6 / double(std::max<std::uint64_t>(1, s.choice_points)), 2) + " us";
    t.notes["passes"] = std::to_string(o.passes);
    add_machine_notes(t);
    return t;
}

namespace {

// The motions of Table 2: the longest clips of the data, or random walks in the graph.
std::vector<std::pair<std::string, Path>> table2_motions(const Table2Options& o) {
    std::vector<std::pair<std::string, Path>> out;
    if (o.synth) {
        const MotionGraph g = load_graph(o.graph);
        Random rng(o.seed ^ 0x5eedull);
        for (int k = 0; k < o.motions; ++k) {
            Path p;
            p.dt = g.dt();
            int clip = rng.below(int(g.clips.size()));
            Placement at;
            std::string name = "walk " + std::to_string(k) + ":";
            while (p.duration() < o.synth_seconds) {
                const Rigid2 m = Rigid2::of(at);
                for (const Sample& s : g.clips[std::size_t(clip)].path.samples)
                    p.samples.push_back({m.apply_x(s.x, s.y), m.apply_y(s.x, s.y), s.r});
                at = g.next(at, clip);
                name += " " + std::to_string(clip);
                const auto& succ = g.clips[std::size_t(clip)].successors;
                clip = succ[std::size_t(rng.below(int(succ.size())))];
            }
            out.emplace_back(name, std::move(p));
        }
        return out;
    }
    const std::string dir = io::data_dir();
    if (dir.empty()) throw std::runtime_error("table2: no mocap data folder (set MOBB_DATA)");
    std::vector<std::string> files;
    for (const auto& e : std::filesystem::directory_iterator(dir + "/cmu"))
        if (e.path().extension() == ".bvh") files.push_back(e.path().string());
    std::sort(files.begin(), files.end());
    io::LoadOptions lo;
    lo.fps = o.fps;
    for (const std::string& f : files) out.emplace_back("cmu/" + std::filesystem::path(f).filename().string(), io::load_clip(f, lo).path);
    std::stable_sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.second.size() > b.second.size(); });
    if (int(out.size()) > o.motions) out.resize(std::size_t(o.motions));
    return out;
}

glm::dvec2 centre(const Path& p) {
    glm::dvec2 c(0.0);
    for (const Sample& s : p.samples) c += glm::dvec2(s.x, s.y);
    return c / double(p.size());
}

// Random tests: b rotated at random, moved so its centre lands uniformly in a disk of radius R about
// a's centre, shifted in time uniformly over the offsets where the two overlap.
std::vector<BenchQuery> random_tests(const std::vector<Path>& clips, double radius, int count, std::uint64_t seed) {
    Random rng(seed);
    std::vector<BenchQuery> out;
    out.reserve(std::size_t(count));
    const int n = int(clips.size());
    for (int k = 0; k < count; ++k) {
        BenchQuery q;
        q.a = rng.below(n);
        q.b = rng.below(n);
        const Path &a = clips[std::size_t(q.a)], &b = clips[std::size_t(q.b)];
        const double theta = rng.uniform(-kPi, kPi);
        const double rr = radius * std::sqrt(rng.uniform()), phi = rng.uniform(-kPi, kPi);
        const glm::dvec2 ca = centre(a), cb = centre(b);
        const double c = std::cos(theta), s = std::sin(theta);
        q.pb.theta = theta;
        q.pb.x = ca.x + rr * std::cos(phi) - (c * cb.x - s * cb.y);
        q.pb.y = ca.y + rr * std::sin(phi) - (s * cb.x + c * cb.y);
        q.pb.t0 = rng.uniform(-b.duration(), a.duration());
        out.push_back(q);
    }
    return out;
}

}  // namespace

namespace {

void add_table2_targets(BenchTable& t, const Table2Options& o) {
    if (!o.synth) {
        t.targets.push_back(speed_target(t, "best scan", 1));
        t.targets.push_back(speed_target(t, "MOBB 1 level", 25));
        t.targets.push_back(speed_target(t, "FCL", 20));
    } else if (o.synth_seconds >= 100) {
        t.targets.push_back(speed_target(t, "best scan", 8));
    } else {
        t.targets.push_back(speed_target(t, "best scan", 2));
    }
}

}  // namespace

BenchTable run_table2(const Table2Options& o, std::vector<std::unique_ptr<QueryMethod>> extra,
                      const std::function<void(double)>& progress) {
    BenchTable t;
    t.workload = !o.workload.empty() ? o.workload : o.synth ? "synth" + fixed(o.synth_seconds, 0) : "table2";
    const auto motions = table2_motions(o);
    if (motions.empty()) throw std::runtime_error("table2: no motions");
    QuerySet set;
    double total = 0;
    std::string names;
    for (const auto& [name, path] : motions) {
        set.clips.push_back(path);
        total += path.duration();
        names += (names.empty() ? "" : ", ") + name + " (" + fixed(path.duration(), 1) + " s)";
    }
    const std::vector<Tree> roots = mobb_trees(set.clips, o.n_min);
    if (progress) progress(0.05);

    double target = o.root_share;
    std::string target_source = "given";
    if (target < 0) {
        const MotionGraph g = load_graph(o.graph);
        CrowdOptions co;
        co.agents = o.crowd_agents;
        co.seconds = o.crowd_seconds;
        co.seed = o.seed;
        co.select = Selection::Random;
        co.log_queries = true;
        const std::vector<Tree> gt = build_trees(g, {});
        const CrowdRun run = run_crowd(g, gt, co);
        std::vector<BenchQuery> qs;
        for (const LoggedQuery& q : run.queries) qs.push_back({q.clip_a, q.clip_b, q.pa, q.pb});
        target = root_share(gt, qs);
        target_source = "measured on a crowd run (" + std::to_string(co.agents) + " agents, 30 x 40 m, " +
                        fixed(co.seconds, 0) + " s, random selection, " + std::to_string(qs.size()) + " queries)";
    }
    if (progress) progress(0.1);

    // Bisection on the radius: the share of root overlaps falls as the radius grows.
    double extent = 0;
    for (const Path& p : set.clips) {
        const glm::dvec2 c = centre(p);
        for (const Sample& s : p.samples) extent = std::max(extent, std::hypot(s.x - c.x, s.y - c.y) + s.r);
    }
    const int calibration = std::min(4000, o.tests);
    double lo = 0, hi = 8 * extent + 10;
    for (int it = 0; it < 30; ++it) {
        const double mid = 0.5 * (lo + hi);
        (root_share(roots, random_tests(set.clips, mid, calibration, o.seed + 1)) > target ? lo : hi) = mid;
    }
    const double radius = 0.5 * (lo + hi);
    set.queries = random_tests(set.clips, radius, o.tests, o.seed);
    const double achieved = root_share(roots, set.queries);
    if (progress) progress(0.15);
    if (!o.save_queries.empty()) save_query_set(set, o.save_queries);

    std::vector<std::unique_ptr<QueryMethod>> methods = bench_methods(o.n_min);
    for (auto& m : extra) methods.push_back(std::move(m));
    t.rows = time_methods(set, methods, o.passes, stage(progress, 0.15, 1.0), o.slow_queries);
    add_table2_targets(t, o);
    t.title = std::string("Table 2: ") + (o.synth ? "motion-graph sequences" : "longest clips") + " (" +
              std::to_string(motions.size()) + " motions, mean " + fixed(total / double(motions.size()), 1) + " s, " +
              std::to_string(o.tests) + " identical random tests)";
    t.notes["motions"] = names;
    t.notes["sampling"] = "dt 1/" + fixed(o.fps, 0) + " s";
    t.notes["root overlap target"] = fixed(100.0 * target, 1) + " %, " + target_source;
    t.notes["root overlap achieved"] = fixed(100.0 * achieved, 1) + " % (MOBB root boxes, all tests)";
    t.notes["translation radius"] = fixed(radius, 3) + " m (uniform disk about the first motion's centre)";
    t.notes["rotation, time offset"] = "uniform in [-pi, pi); uniform over the offsets where the motions overlap in time";
    t.notes["passes"] = std::to_string(o.passes);
    t.notes["seed"] = std::to_string(o.seed);
    add_machine_notes(t);
    if (progress) progress(1.0);
    return t;
}

}  // namespace mobb::crowd
