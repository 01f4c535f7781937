#include "colouring.h"

#include <algorithm>
#include <cmath>

#include "box_layer.h"
#include "mobb/core/clearance.h"
#include "mobb/core/path.h"
#include "mobb/core/trace.h"
#include "mobb/core/tree.h"
#include "state.h"

namespace mobb::viewer {

namespace {

using render::BoxColour;
using render::ColourMap;
using render::DiskColour;

/// The least and the q-quantile of the finite values.
std::pair<double, double> range_of(const std::vector<std::vector<float>>& values, double q) {
    std::vector<float> all;
    for (const auto& v : values)
        for (float x : v)
            if (std::isfinite(x)) all.push_back(x);
    if (all.empty()) return {0.0, 1.0};
    const auto k = std::size_t(q * double(all.size() - 1));
    std::nth_element(all.begin(), all.begin() + std::ptrdiff_t(k), all.end());
    const double hi = all[k];
    return {double(*std::min_element(all.begin(), all.end())), hi};
}

std::vector<float> to_float(const std::vector<double>& v) { return {v.begin(), v.end()}; }

}  // namespace

std::vector<std::vector<float>> sample_values(const State& s, DiskColour colour) {
    std::vector<std::vector<float>> out(s.clips.size());
    if (colour == DiskColour::Clearance) {
        std::vector<const Path*> paths;
        for (const LoadedClip& c : s.clips) paths.push_back(&c.tree->path());
        const auto gaps = nearest_clearance(paths, s.places);
        for (std::size_t k = 0; k < gaps.size(); ++k) out[k] = to_float(gaps[k]);
        return out;
    }
    for (std::size_t k = 0; k < s.clips.size(); ++k) {
        const Path& path = s.clips[k].tree->path();
        std::vector<float>& v = out[k];
        switch (colour) {
            case DiskColour::Clip: break;
            case DiskColour::Radius:
                for (const Sample& x : path.samples) v.push_back(float(x.r));
                break;
            case DiskColour::Speed: v = to_float(sample_speeds(path)); break;
            case DiskColour::Time:
                for (std::size_t i = 0; i < path.size(); ++i)
                    v.push_back(float(sample_time(s.places[k], path.dt, std::int64_t(i))));
                break;
            case DiskColour::Clearance: break;
        }
    }
    return out;
}

std::vector<std::vector<float>> node_values(const State& s, BoxColour colour) {
    std::vector<std::vector<float>> out(s.clips.size());
    for (std::size_t k = 0; k < s.clips.size(); ++k) {
        const Tree& tree = *s.clips[k].tree;
        if (colour == BoxColour::Tightness) {
            for (const Node& n : tree.nodes()) out[k].push_back(float(volume_ratio(tree, n)));
        } else if (colour == BoxColour::Tests) {
            // The shown query's trees: A's nodes counted on side A, B's on side B; other clips untested.
            const bool a = int(k) == s.scene.query_a, b = int(k) == s.scene.query_b;
            std::vector<int> count(tree.nodes().size(), 0);
            if (s.queried && (a || b)) count = tests_per_node(s.trace, a, tree.nodes().size());
            out[k].assign(count.begin(), count.end());
        }
    }
    return out;
}

render::ColourScale disk_scale(DiskColour colour, const std::vector<std::vector<float>>& values) {
    render::ColourScale scale;
    if (colour == DiskColour::Clearance) {
        scale.map = ColourMap::Diverging;
        // Reversed: overlaps (below 0) warm, clear space cool.
        scale.lo = kClearanceRange;
        scale.hi = -kClearanceRange;
        scale.label = "clearance";
        scale.unit = "m";
        return scale;
    }
    const auto [lo, hi] = range_of(values, 0.99);
    scale.lo = colour == DiskColour::Speed ? 0.0 : lo;
    scale.hi = std::max(hi, scale.lo + 1e-6);
    scale.label = colour == DiskColour::Radius ? "radius" : colour == DiskColour::Speed ? "speed" : "time";
    scale.unit = colour == DiskColour::Radius ? "m" : colour == DiskColour::Speed ? "m/s" : "s";
    return scale;
}

render::ColourScale box_scale(BoxColour colour, const std::vector<std::vector<float>>& values) {
    render::ColourScale scale;
    const auto [lo, hi] = range_of(values, colour == BoxColour::Tests ? 1.0 : 0.99);
    scale.lo = colour == BoxColour::Tests ? 0.0 : std::min(lo, 1.0);
    scale.hi = std::max(hi, scale.lo + 1.0);
    scale.label = colour == BoxColour::Tests ? "tests by the query" : "tightness";
    scale.unit = colour == BoxColour::Tests ? "count" : "box / disks volume";
    return scale;
}

void update_colouring(const State& s, Colouring& c) {
    const render::Layers& l = s.scene.layers;
    Colouring::Key key{s.revision,   l.disk_colour, l.box_colour,   l.level,         l.levels,
                       l.all_levels, &s.trace,      s.trace.size(), s.scene.query_a, s.scene.query_b};
    if (c.valid && key == c.key) return;
    const bool disks = !c.valid || key.revision != c.key.revision || key.disks != c.key.disks;
    if (disks) {
        c.samples = sample_values(s, l.disk_colour);
        c.disk_scale = disk_scale(l.disk_colour, c.samples);
    }
    c.nodes = node_values(s, l.box_colour);
    // The range over the boxes drawn: a level's ratios differ from the root's by far.
    std::vector<std::vector<float>> shown(c.nodes.size());
    for (std::size_t k = 0; k < c.nodes.size(); ++k) {
        const auto& nodes = s.clips[k].tree->nodes();
        for (std::size_t n = 0; n < c.nodes[k].size() && n < nodes.size(); ++n)
            if (l.all_levels || render::shown_at_level(nodes[n], l.level, l.levels)) shown[k].push_back(c.nodes[k][n]);
    }
    c.box_scale = box_scale(l.box_colour, shown);
    c.key = key;
    c.valid = true;
    ++c.serial;
}

}  // namespace mobb::viewer
