#include "sequences.h"

#include <cmath>
#include <map>
#include <random>
#include <stdexcept>
#include <utility>

#include "mobb/io/load.h"

namespace mobb::bench {

namespace {

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

const std::vector<std::vector<const char*>> kParts = {{"001_01", "001_08"}, {"001_14", "002_05", "005_02"}};
bool g_fallback = false;

}  // namespace

Path concatenate(const std::vector<Path>& parts, double seconds) {
    if (parts.empty()) throw std::invalid_argument("concatenate: no parts");
    Path out;
    out.dt = parts.front().dt;
    const auto n = std::size_t(std::llround(seconds / out.dt));
    for (const Path& p : parts) {
        if (p.samples.empty()) continue;
        double dx = 0, dy = 0;
        if (!out.samples.empty()) dx = out.samples.back().x - p.samples.front().x, dy = out.samples.back().y - p.samples.front().y;
        for (const Sample& s : p.samples) {
            if (out.samples.size() == n) return out;
            out.samples.push_back({s.x + dx, s.y + dy, s.r});
        }
    }
    return out;
}

const Path& sequence42(int which, double fps) {
    static std::map<std::pair<int, double>, Path> cache;
    const auto key = std::make_pair(which, fps);
    auto it = cache.find(key);
    if (it != cache.end()) return it->second;
    Path path;
    const std::string dir = io::data_dir();
    try {
        if (dir.empty()) throw std::runtime_error("no data");
        std::vector<Path> parts;
        io::LoadOptions o;
        o.fps = fps;
        for (const char* name : kParts[std::size_t(which)])
            parts.push_back(io::load_clip(dir + "/cmu/" + name + ".bvh", o).path);
        path = concatenate(parts, 42.0);
    } catch (const std::exception&) {
        g_fallback = true;
        std::mt19937_64 rng(std::uint64_t(which) + 1);
        path = random_walk(rng, std::size_t(42.0 * fps), 1.0 / fps);
    }
    return cache.emplace(key, std::move(path)).first->second;
}

std::string source() { return g_fallback ? "random walk" : "cmu"; }

Placements random_placements(double duration, std::size_t count, unsigned seed) {
    Placements out;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    for (std::size_t i = 0; i < count; ++i) {
        out.a.push_back({0, 0, 0, 0});
        out.b.push_back({8 * (u(rng) - 0.5), 8 * (u(rng) - 0.5), 6.283185307179586 * u(rng), duration * (u(rng) - 0.5)});
    }
    return out;
}

}  // namespace mobb::bench
