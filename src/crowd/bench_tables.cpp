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

std::string fixed(double v, int digits) {
    std::ostringstream s;
    s.setf(std::ios::fixed);
    s.precision(digits);
    s << v;
    return s.str();
}

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

std::vector<MethodRow> time_methods(const QuerySet& set, const std::vector<std::unique_ptr<QueryMethod>>& methods,
                                    int passes, const std::function<void(double)>& progress) {
    const std::size_t n = set.queries.size();
    std::vector<MethodRow> rows(methods.size());
    std::vector<std::vector<bool>> answers(methods.size());
    for (std::size_t m = 0; m < methods.size(); ++m) {
        methods[m]->prepare(set.clips);
        QueryStats st;
        std::uint64_t pos = 0;
        for (const BenchQuery& q : set.queries) {
            const bool hit = methods[m]->query(q.a, q.pa, q.b, q.pb, &st);
            answers[m].push_back(hit);
            pos += hit;
        }
        MethodRow& r = rows[m];
        r.method = methods[m]->name();
        r.queries = n;
        const double d = double(std::max<std::size_t>(1, n));
        r.tests2d = double(st.tests2d) / d;
        r.tests3d = double(st.tests3d) / d;
        r.samples = double(st.samples) / d;
        r.positive = double(pos) / d;
        if (progress) progress(0.2 * double(m + 1) / double(methods.size()));
    }
    std::size_t ref = methods.size();
    for (std::size_t m = 0; m < methods.size(); ++m)
        if (rows[m].method == "brute force") ref = m;
    if (ref < methods.size())
        for (std::size_t m = 0; m < methods.size(); ++m)
            for (std::size_t k = 0; k < n; ++k) rows[m].disagreements += answers[m][k] != answers[ref][k];

    std::vector<std::vector<double>> times(methods.size());
    volatile bool sink = false;
    for (int p = 0; p < passes; ++p)
        for (std::size_t m = 0; m < methods.size(); ++m) {
            const auto t0 = Clock::now();
            bool acc = false;
            for (const BenchQuery& q : set.queries) acc ^= methods[m]->query(q.a, q.pa, q.b, q.pb, nullptr);
            times[m].push_back(seconds_since(t0) * 1e6 / double(std::max<std::size_t>(1, n)));
            sink = sink ^ acc;
            if (progress) progress(0.2 + 0.8 * double(std::size_t(p) * methods.size() + m + 1) / double(std::size_t(passes) * methods.size()));
        }
    for (std::size_t m = 0; m < methods.size(); ++m) rows[m].us_per_query = median(times[m]);
    return rows;
}

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
    std::vector<std::unique_ptr<QueryMethod>> methods = paper_methods(o.n_min);
    for (auto& m : extra) methods.push_back(std::move(m));

    BenchTable t;
    t.workload = "table1";
    t.title = "Table 1: crowd workload (" + std::to_string(o.agents) + " agents, " + fixed(o.width, 0) + " x " +
              fixed(o.height, 0) + " m, " + fixed(o.seconds, 0) + " s, random selection)";
    t.rows = time_methods(set, methods, o.passes, stage(progress, 0.1, 0.95));

    const FrameSteppingResult fs = frame_stepping(g, run.record);
    MethodRow step;
    step.method = "frame stepping";
    step.queries = set.queries.size();
    const double nq = double(std::max<std::size_t>(1, set.queries.size()));
    step.us_per_query = (fs.build_seconds + fs.check_seconds) * 1e6 / nq;
    step.samples = double(fs.disk_tests) / nq;
    step.positive = fs.candidates ? double(fs.positive) / double(fs.candidates) : 0.0;
    step.disagreements = fs.disagreements;
    step.note = "per candidate, not per query; time = (grid build + stepping) / queries";
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

BenchTable run_table2(const Table2Options& o, std::vector<std::unique_ptr<QueryMethod>> extra,
                      const std::function<void(double)>& progress) {
    BenchTable t;
    t.workload = o.synth ? "table2 --synth" : "table2";
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

    std::vector<std::unique_ptr<QueryMethod>> methods = paper_methods(o.n_min);
    for (auto& m : extra) methods.push_back(std::move(m));
    t.rows = time_methods(set, methods, o.passes, stage(progress, 0.15, 1.0));
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

std::string table_markdown(const BenchTable& t) {
    std::ostringstream out;
    out << "### " << t.title << "\n\n"
        << "| Method | Time (us) | #2D | #3D | #sample | positive | differs from brute force |\n"
        << "|---|---:|---:|---:|---:|---:|---:|\n";
    for (const MethodRow& r : t.rows)
        out << "| " << r.method << " | " << fixed(r.us_per_query, 3) << " | " << fixed(r.tests2d, 2) << " | "
            << fixed(r.tests3d, 2) << " | " << fixed(r.samples, 2) << " | " << fixed(100.0 * r.positive, 1) << " % | "
            << r.disagreements << (r.note.empty() ? "" : " (" + r.note + ")") << " |\n";
    out << "\n";
    for (const auto& [k, v] : t.notes) out << "- " << k << ": " << v << "\n";
    return out.str();
}

std::string table_json(const BenchTable& t) {
    nlohmann::ordered_json j;
    j["workload"] = t.workload;
    j["title"] = t.title;
    nlohmann::ordered_json notes = nlohmann::ordered_json::object();
    for (const auto& [k, v] : t.notes) notes[k] = v;
    j["notes"] = notes;
    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    for (const MethodRow& r : t.rows)
        rows.push_back({{"method", r.method}, {"us_per_query", rounded(r.us_per_query, 4)}, {"tests2d", rounded(r.tests2d, 4)},
                        {"tests3d", rounded(r.tests3d, 4)}, {"samples", rounded(r.samples, 4)},
                        {"positive", rounded(r.positive, 6)}, {"queries", r.queries}, {"disagreements", r.disagreements},
                        {"note", r.note}});
    j["rows"] = rows;
    return readable_json(j);
}

void write_table_png(const BenchTable& t, const std::string& file) {
    std::vector<Bar> bars;
    for (const MethodRow& r : t.rows) bars.push_back({r.method, r.us_per_query});
    write_bar_chart(file, t.title, bars, "us/query");
}

}  // namespace mobb::crowd
