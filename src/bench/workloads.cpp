#include "workloads.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
#include <stdexcept>

#include <glm/vec2.hpp>

#include "method.h"
#include "mobb/core/angle.h"
#include "mobb/io/load.h"
#include "mobb/util/random.h"

namespace mobb::bench {

namespace {

glm::dvec2 centre(const Path& p) {
    glm::dvec2 c(0.0);
    for (const Sample& s : p.samples) c += glm::dvec2(s.x, s.y);
    return c / double(p.size());
}

// A smooth random walk at 1.3 m/s: the stand-in for a sequence when the data folder is missing.
Path random_walk(std::mt19937_64& rng, std::size_t n, double dt) {
    std::uniform_real_distribution<double> u(0, 1);
    Path p;
    p.dt = dt;
    double x = 0, y = 0, h = 0;
    for (std::size_t i = 0; i < n; ++i) {
        h += 0.05 * (u(rng) - 0.5);
        x += 1.3 * dt * std::cos(h), y += 1.3 * dt * std::sin(h);
        p.samples.push_back({x, y, 0.3 + 0.1 * u(rng)});
    }
    return p;
}

// One ~42 s sequence of real clips joined end to end; throws without the data.
Path real_sequence42(int which, double fps) {
    static const std::vector<std::vector<const char*>> kParts = {{"001_01", "001_08"}, {"001_14", "002_05", "005_02"}};
    const std::string dir = io::data_dir();
    if (dir.empty()) throw std::runtime_error("no data folder");
    std::vector<Path> parts;
    io::LoadOptions o;
    o.fps = fps;
    for (const char* name : kParts[std::size_t(which)])
        parts.push_back(io::load_clip(dir + "/cmu/" + name + ".bvh", o).path);
    return concatenate(parts, 42.0);
}

}  // namespace

QuerySet crowd_query_set(const crowd::MotionGraph& graph, const std::vector<crowd::LoggedQuery>& queries) {
    QuerySet set;
    for (const crowd::GraphClip& c : graph.clips) set.clips.push_back(c.path);
    for (const crowd::LoggedQuery& q : queries) set.queries.push_back({q.clip_a, q.clip_b, q.pa, q.pb});
    return set;
}

std::vector<NamedPath> longest_clips(int count, double fps) {
    const std::string dir = io::data_dir();
    if (dir.empty()) throw std::runtime_error("no mocap data folder (set MOBB_DATA)");
    std::vector<std::string> files;
    for (const auto& e : std::filesystem::directory_iterator(dir + "/cmu"))
        if (e.path().extension() == ".bvh") files.push_back(e.path().string());
    std::sort(files.begin(), files.end());
    io::LoadOptions lo;
    lo.fps = fps;
    std::vector<NamedPath> out;
    out.reserve(files.size());
    for (const std::string& f : files)
        out.push_back({"cmu/" + std::filesystem::path(f).filename().string(), io::load_clip(f, lo).path});
    std::stable_sort(out.begin(), out.end(),
                     [](const auto& a, const auto& b) { return a.path.size() > b.path.size(); });
    if (int(out.size()) > count) out.resize(std::size_t(count));
    return out;
}

std::vector<NamedPath> graph_walks(const crowd::MotionGraph& g, int count, double seconds, std::uint64_t seed) {
    std::vector<NamedPath> out;
    util::Random rng(seed);
    for (int k = 0; k < count; ++k) {
        Path p;
        p.dt = g.dt();
        int clip = rng.below(int(g.clips.size()));
        Placement at;
        std::string name = "walk " + std::to_string(k) + ":";
        while (p.duration() < seconds) {
            const Rigid2 m = Rigid2::of(at);
            for (const Sample& s : g.clips[std::size_t(clip)].path.samples)
                p.samples.push_back({m.apply_x(s.x, s.y), m.apply_y(s.x, s.y), s.r});
            at = g.next(at, clip);
            name += " " + std::to_string(clip);
            const auto& succ = g.clips[std::size_t(clip)].successors;
            clip = succ[std::size_t(rng.below(int(succ.size())))];
        }
        out.push_back({name, std::move(p)});
    }
    return out;
}

std::vector<ClipQuery> random_tests(const std::vector<Path>& clips, double radius, int count, std::uint64_t seed) {
    util::Random rng(seed);
    std::vector<ClipQuery> out;
    out.reserve(std::size_t(count));
    const int n = int(clips.size());
    for (int k = 0; k < count; ++k) {
        ClipQuery q;
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

std::vector<Tree> mobb_trees(const std::vector<Path>& clips, int n_min) {
    std::vector<Tree> out;
    out.reserve(clips.size());
    for (const Path& p : clips) out.push_back(Tree::build(p, {TreeType::Mobb, n_min}));
    return out;
}

double root_share(const std::vector<Tree>& trees, const std::vector<ClipQuery>& queries) {
    std::uint64_t roots = 0;
    for (const ClipQuery& q : queries)
        if (root_boxes_overlap(trees[std::size_t(q.a)], q.pa, trees[std::size_t(q.b)], q.pb)) ++roots;
    return queries.empty() ? 0.0 : double(roots) / double(queries.size());
}

double radius_for_root_share(const std::vector<Path>& clips, const std::vector<Tree>& trees, double target,
                             int calibration, std::uint64_t seed) {
    double extent = 0;
    for (const Path& p : clips) {
        const glm::dvec2 c = centre(p);
        for (const Sample& s : p.samples) extent = std::max(extent, std::hypot(s.x - c.x, s.y - c.y) + s.r);
    }
    double lo = 0, hi = 8 * extent + 10;
    for (int it = 0; it < 30; ++it) {
        const double mid = 0.5 * (lo + hi);
        (root_share(trees, random_tests(clips, mid, calibration, seed)) > target ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

Path concatenate(const std::vector<Path>& parts, double seconds) {
    if (parts.empty()) throw std::invalid_argument("concatenate: no parts");
    Path out;
    out.dt = parts.front().dt;
    const auto n = std::size_t(std::llround(seconds / out.dt));
    for (const Path& p : parts) {
        if (p.samples.empty()) continue;
        double dx = 0, dy = 0;
        if (!out.samples.empty())
            dx = out.samples.back().x - p.samples.front().x, dy = out.samples.back().y - p.samples.front().y;
        for (const Sample& s : p.samples) {
            if (out.samples.size() == n) return out;
            out.samples.push_back({s.x + dx, s.y + dy, s.r});
        }
    }
    return out;
}

QuerySet sequence42_set(double fps, std::string* source) {
    QuerySet set;
    try {
        for (int which = 0; which < 2; ++which) set.clips.push_back(real_sequence42(which, fps));
        if (source) *source = "cmu";
    } catch (const std::exception&) {
        set.clips.clear();
        for (int which = 0; which < 2; ++which) {
            std::mt19937_64 rng(std::uint64_t(which) + 1);
            set.clips.push_back(random_walk(rng, std::size_t(42.0 * fps), 1.0 / fps));
        }
        if (source) *source = "random walk";
    }
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<double> u(0, 1);
    const double d = set.clips[0].duration();
    for (int i = 0; i < 4096; ++i)
        set.queries.push_back(
            {0, 1, {0, 0, 0, 0}, {8 * (u(rng) - 0.5), 8 * (u(rng) - 0.5), 2 * kPi * u(rng), d * (u(rng) - 0.5)}});
    return set;
}

}  // namespace mobb::bench
