#include "scenario/steersuite_shapes.h"

#include <algorithm>
#include <cmath>

#include "mobb/core/angle.h"
#include "mobb/util/json_text.h"

namespace mobb::crowd::steersuite {

namespace {

using Point = std::array<double, 2>;

constexpr double kMicrometre = 1e-6;

Point rounded(const Point& p) { return {util::rounded(p[0]), util::rounded(p[1])}; }

double distance2(const Point& p, const Point& a, const Point& b) {
    const double ex = b[0] - a[0], ey = b[1] - a[1], wx = p[0] - a[0], wy = p[1] - a[1];
    const double len2 = ex * ex + ey * ey;
    const double t = len2 > 0 ? std::clamp((wx * ex + wy * ey) / len2, 0.0, 1.0) : 0.0;
    const double dx = wx - t * ex, dy = wy - t * ey;
    return dx * dx + dy * dy;
}

// Even-odd rule; a segment or a point holds nothing.
bool inside(const Polygon& poly, const Point& p) {
    const auto& v = poly.vertices;
    bool in = false;
    for (std::size_t i = 0, j = v.size() - 1; v.size() >= 3 && i < v.size(); j = i++)
        if ((v[i][1] > p[1]) != (v[j][1] > p[1]) &&
            p[0] < v[j][0] + (p[1] - v[j][1]) * (v[i][0] - v[j][0]) / (v[i][1] - v[j][1]))
            in = !in;
    return in;
}

double cross(const Point& o, const Point& a, const Point& b) {
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

// Segments a-b and c-d cross at a point inside both (touching ends are found by distance instead).
bool cross_properly(const Point& a, const Point& b, const Point& c, const Point& d) {
    const double d1 = cross(a, b, c), d2 = cross(a, b, d), d3 = cross(c, d, a), d4 = cross(c, d, b);
    return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

// The smallest squared distance from a vertex of `a` to an edge of `b`; true when edges cross.
bool nearest(const Polygon& a, const Polygon& b, double& d2) {
    const auto& u = a.vertices;
    const auto& v = b.vertices;
    for (std::size_t i = 0; i < u.size(); ++i)
        for (std::size_t k = 0, j = v.size() - 1; k < v.size(); j = k++) {
            d2 = std::min(d2, distance2(u[i], v[j], v[k]));
            if (u.size() > 1 && cross_properly(u[i], u[(i + 1) % u.size()], v[j], v[k])) return true;
        }
    return false;
}

// Sutherland-Hodgman: the polygon's part on the side of an axis-aligned line where `keep` holds.
template <class Keep, class Cut>
std::vector<Point> clip_side(const std::vector<Point>& in, Keep keep, Cut cut) {
    std::vector<Point> out;
    for (std::size_t i = 0, j = in.size() - 1; i < in.size(); j = i++) {
        const bool now = keep(in[i]), before = keep(in[j]);
        if (now != before) out.push_back(cut(in[j], in[i]));
        if (now) out.push_back(in[i]);
    }
    return out;
}

}  // namespace

int circle_sides(double r) {
    for (int n = kFewestSides; n < kMostSides; ++n)
        if (r * (1 / std::cos(kPi / n) - 1) <= kCircleReach) return n;
    return kMostSides;
}

double circle_reach(double r) { return (r + kMicrometre) / std::cos(kPi / circle_sides(r)) - r; }

Polygon circle_polygon(double x, double y, double r) {
    const int n = circle_sides(r);
    const double corner = (r + kMicrometre) / std::cos(kPi / n);  // the edges' distance from the centre: r + 1 um
    Polygon p;
    for (int k = 0; k < n; ++k) {
        const double a = 2 * kPi * k / n;
        p.vertices.push_back(rounded({x + corner * std::cos(a), y + corner * std::sin(a)}));
    }
    return p;
}

Polygon oriented_rectangle(double x, double y, double lx, double lz, double theta_y) {
    const double a = radians(theta_y), c = std::cos(a), s = std::sin(a);
    const auto place = [&](double u, double w) { return rounded({x + u * c + w * s, y + w * c - u * s}); };
    const double hx = lx / 2, hz = lz / 2;
    Polygon p;
    if (lx > 0 && lz > 0)
        p.vertices = {place(-hx, -hz), place(hx, -hz), place(hx, hz), place(-hx, hz)};
    else if (lx > 0 || lz > 0)
        p.vertices = {place(-hx, -hz), place(hx, hz)};
    else
        p.vertices = {place(0, 0)};
    return p;
}

Polygon clipped(const Polygon& p, const World& w) {
    std::vector<Point> v = p.vertices;
    const auto at_x = [](double x) {
        return [x](const Point& a, const Point& b) {
            return Point{x, a[1] + (x - a[0]) * (b[1] - a[1]) / (b[0] - a[0])};
        };
    };
    const auto at_y = [](double y) {
        return [y](const Point& a, const Point& b) {
            return Point{a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1]), y};
        };
    };
    if (!v.empty())
        v = clip_side(
            v, [&](const Point& q) { return q[0] >= w.x0; }, at_x(w.x0));
    if (!v.empty())
        v = clip_side(
            v, [&](const Point& q) { return q[0] <= w.x1; }, at_x(w.x1));
    if (!v.empty())
        v = clip_side(
            v, [&](const Point& q) { return q[1] >= w.y0; }, at_y(w.y0));
    if (!v.empty())
        v = clip_side(
            v, [&](const Point& q) { return q[1] <= w.y1; }, at_y(w.y1));
    Polygon out;
    for (const Point& q : v)
        if (out.vertices.empty() || rounded(q) != out.vertices.back()) out.vertices.push_back(rounded(q));
    while (out.vertices.size() > 1 && out.vertices.back() == out.vertices.front()) out.vertices.pop_back();
    return out;
}

double gap(const Polygon& a, const Polygon& b) {
    if (a.vertices.empty() || b.vertices.empty()) return INFINITY;
    if (inside(b, a.vertices[0]) || inside(a, b.vertices[0])) return 0;
    double d2 = INFINITY;
    if (nearest(a, b, d2) || nearest(b, a, d2)) return 0;
    return std::sqrt(d2);
}

double gap(const Polygon& p, double x, double y) { return gap(p, Polygon{{{x, y}}}); }

double nearest_edge_angle(const Polygon& p, double x, double y) {
    const auto& v = p.vertices;
    if (v.size() < 2) return std::atan2(v[0][1] - y, v[0][0] - x) + kPi / 2;
    double best = INFINITY, angle = 0;
    for (std::size_t i = 0; i < v.size(); ++i) {
        const auto& a = v[i];
        const auto& b = v[(i + 1) % v.size()];
        const double dx = b[0] - a[0], dy = b[1] - a[1], len2 = dx * dx + dy * dy;
        if (len2 == 0) continue;
        const double u = std::clamp(((x - a[0]) * dx + (y - a[1]) * dy) / len2, 0.0, 1.0);
        const double d = std::hypot(a[0] + u * dx - x, a[1] + u * dy - y);
        if (d < best) best = d, angle = std::atan2(dy, dx);
    }
    return angle;
}

}  // namespace mobb::crowd::steersuite
