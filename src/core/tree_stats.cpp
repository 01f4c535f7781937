#include <algorithm>
#include <cmath>
#include <vector>

#include "mobb/core/angle.h"
#include "mobb/core/tree.h"

namespace mobb {

namespace {

// Area of the union of the disks of samples [first, end), rasterised on a grid fine enough for
// ~0.1% error on typical paths (cell at most 1/32 of the smallest positive radius).
double disk_union_area(const Path& path, std::size_t first, std::size_t end) {
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY, rmin = INFINITY;
    for (std::size_t i = first; i < end; ++i) {
        const Sample& s = path.samples[i];
        x0 = std::min(x0, s.x - s.r), y0 = std::min(y0, s.y - s.r);
        x1 = std::max(x1, s.x + s.r), y1 = std::max(y1, s.y + s.r);
        if (s.r > 0) rmin = std::min(rmin, s.r);
    }
    if (!std::isfinite(rmin)) return 0;
    const double cell = std::max({rmin / 32, (x1 - x0) / 4096, (y1 - y0) / 4096});
    const int nx = int(std::ceil((x1 - x0) / cell)) + 1, ny = int(std::ceil((y1 - y0) / cell)) + 1;
    std::vector<unsigned char> covered(std::size_t(nx) * std::size_t(ny), 0);
    for (std::size_t i = first; i < end; ++i) {
        const Sample& s = path.samples[i];
        const int ya = std::max(0, int((s.y - s.r - y0) / cell)), yb = std::min(ny - 1, int((s.y + s.r - y0) / cell));
        for (int y = ya; y <= yb; ++y) {
            const double cy = y0 + (y + 0.5) * cell - s.y;
            const double w2 = s.r * s.r - cy * cy;
            if (w2 < 0) continue;
            const double w = std::sqrt(w2);
            const int xa = std::max(0, int(std::ceil((s.x - w - x0) / cell - 0.5)));
            const int xb = std::min(nx - 1, int(std::floor((s.x + w - x0) / cell - 0.5)));
            for (int x = xa; x <= xb; ++x) covered[std::size_t(y) * std::size_t(nx) + std::size_t(x)] = 1;
        }
    }
    return double(std::count(covered.begin(), covered.end(), 1)) * cell * cell;
}

double cylinders_volume(const Path& path, std::size_t first, std::size_t end) {
    double v = 0;
    for (std::size_t i = first; i < end; ++i) v += kPi * path.samples[i].r * path.samples[i].r * path.dt;
    return v;
}

}  // namespace

double volume_ratio(const Tree& tree, const Node& node) {
    return tree.box3(node).volume() / std::max(cylinders_volume(tree.path(), node.first, node.end), 1e-300);
}

std::vector<LevelStats> level_stats(const Tree& tree) {
    std::vector<LevelStats> levels(std::size_t(tree.depth()));
    std::vector<int> area_count(levels.size(), 0);
    for (std::size_t l = 0; l < levels.size(); ++l) levels[l].level = int(l);
    for (const Node& node : tree.nodes()) {
        LevelStats& s = levels[node.level];
        ++s.nodes;
        const double volume = tree.box3(node).volume();
        s.mean_volume += volume;
        s.volume_ratio += volume_ratio(tree, node);
        if (node.kind == BoxKind::Box2) {
            ++s.box2;
            const double area = tree.box2s()[node.box].area();
            s.mean_area += area;
            s.area_ratio += area / std::max(disk_union_area(tree.path(), node.first, node.end), 1e-300);
        } else {
            ++s.box3;
        }
    }
    for (LevelStats& s : levels) {
        s.mean_volume /= s.nodes;
        s.volume_ratio /= s.nodes;
        if (s.box2) s.mean_area /= s.box2, s.area_ratio /= s.box2;
    }
    return levels;
}

bool all_samples_contained(const Tree& tree, double tol) {
    const Path& path = tree.path();
    for (const Node& node : tree.nodes()) {
        const Obb3 box = tree.box3(node);
        for (std::uint32_t i = node.first; i < node.end; ++i)
            if (!contains(box, path.samples[i], double(i) * path.dt, path.dt, tol)) return false;
    }
    return true;
}

}  // namespace mobb
