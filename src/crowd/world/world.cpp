#include "mobb/crowd/world/world.h"

#include <algorithm>
#include <cmath>

namespace mobb::crowd {

namespace {

// Squared distance from (px, py) to the segment a-b.
double segment_distance2(double px, double py, const std::array<double, 2>& a, const std::array<double, 2>& b) {
    const double ex = b[0] - a[0], ey = b[1] - a[1];
    const double wx = px - a[0], wy = py - a[1];
    const double len2 = ex * ex + ey * ey;
    double t = len2 > 0 ? (wx * ex + wy * ey) / len2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    const double dx = wx - t * ex, dy = wy - t * ey;
    return dx * dx + dy * dy;
}

// Even-odd rule: a ray to +x crosses the boundary an odd number of times.
bool inside(const Polygon& poly, double x, double y) {
    const auto& v = poly.vertices;
    if (v.size() < 3) return false;
    bool in = false;
    for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
        const bool crosses = (v[i][1] > y) != (v[j][1] > y);
        if (crosses && x < v[j][0] + (y - v[j][1]) * (v[i][0] - v[j][0]) / (v[i][1] - v[j][1])) in = !in;
    }
    return in;
}

// An axis-aligned rectangle (walls, most obstacles): the distance by clamping.
bool rectangle(const Polygon& poly, std::array<double, 4>& box) {
    const auto& v = poly.vertices;
    if (v.size() != 4) return false;
    const bool a = v[0][1] == v[1][1] && v[1][0] == v[2][0] && v[2][1] == v[3][1] && v[3][0] == v[0][0];
    const bool b = v[0][0] == v[1][0] && v[1][1] == v[2][1] && v[2][0] == v[3][0] && v[3][1] == v[0][1];
    if (!a && !b) return false;
    box = {std::min(v[0][0], v[2][0]), std::min(v[0][1], v[2][1]), std::max(v[0][0], v[2][0]),
           std::max(v[0][1], v[2][1])};
    return true;
}

}  // namespace

Polygon Polygon::rectangle(double x0, double y0, double x1, double y1) {
    return {{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}};
}

bool disk_overlaps(const Polygon& poly, double x, double y, double r) {
    const auto& v = poly.vertices;
    if (v.empty()) return false;
    std::array<double, 4> b;
    if (rectangle(poly, b)) {
        const double dx = std::max({b[0] - x, 0.0, x - b[2]}), dy = std::max({b[1] - y, 0.0, y - b[3]});
        return (dx == 0 && dy == 0) || dx * dx + dy * dy < r * r;
    }
    if (inside(poly, x, y)) return true;
    const double rr = r * r;
    if (v.size() == 1) return segment_distance2(x, y, v[0], v[0]) < rr;
    for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++)
        if (segment_distance2(x, y, v[j], v[i]) < rr) return true;
    return false;
}

std::array<double, 4> bounds(const Polygon& poly) {
    std::array<double, 4> b = {1e300, 1e300, -1e300, -1e300};
    for (const auto& p : poly.vertices) {
        b[0] = std::min(b[0], p[0]);
        b[1] = std::min(b[1], p[1]);
        b[2] = std::max(b[2], p[0]);
        b[3] = std::max(b[3], p[1]);
    }
    return b;
}

bool path_hits(const Path& path, const Placement& place, const Polygon& poly, std::size_t first) {
    return path_hits(path, Rigid2::of(place), poly, first);
}

bool path_hits(const Path& path, const Rigid2& m, const Polygon& poly, std::size_t first) {
    for (std::size_t i = first; i < path.size(); ++i) {
        const Sample& s = path.samples[i];
        if (disk_overlaps(poly, m.apply_x(s.x, s.y), m.apply_y(s.x, s.y), s.r)) return true;
    }
    return false;
}

std::vector<Polygon> World::solids() const {
    std::vector<Polygon> out = obstacles;
    if (walls) {
        const double t = 1.0;
        out.push_back(Polygon::rectangle(x0 - t, y0 - t, x0, y1 + t));
        out.push_back(Polygon::rectangle(x1, y0 - t, x1 + t, y1 + t));
        out.push_back(Polygon::rectangle(x0, y0 - t, x1, y0));
        out.push_back(Polygon::rectangle(x0, y1, x1, y1 + t));
    }
    return out;
}

}  // namespace mobb::crowd
