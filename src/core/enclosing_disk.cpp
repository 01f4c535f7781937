#include "mobb/core/enclosing_disk.h"

#include <algorithm>
#include <cmath>

namespace mobb {

namespace {

// Within the disk, with a relative slack of a few ulps so that rounding in the circumcentre does not
// send the search round again for a point on the circle; the final pass makes the radius exact.
bool holds(const Sample& d, const glm::dvec2& p) { return std::hypot(p.x - d.x, p.y - d.y) <= d.r * (1 + 1e-12); }

Sample diameter(const glm::dvec2& a, const glm::dvec2& b) {
    return {(a.x + b.x) / 2, (a.y + b.y) / 2, std::hypot(a.x - b.x, a.y - b.y) / 2};
}

// The circle through a, b and c; for (nearly) collinear points, the widest of the three diameters.
Sample circumcircle(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
    const double d = 2 * (a.x * (b.y - c.y) + b.x * (c.y - a.y) + c.x * (a.y - b.y));
    const double scale = std::max({std::hypot(b.x - a.x, b.y - a.y), std::hypot(c.x - a.x, c.y - a.y), 1e-300});
    if (std::abs(d) <= 1e-12 * scale * scale) {
        Sample w = diameter(a, b);
        for (const Sample& s : {diameter(a, c), diameter(b, c)})
            if (s.r > w.r) w = s;
        return w;
    }
    const double a2 = a.x * a.x + a.y * a.y, b2 = b.x * b.x + b.y * b.y, c2 = c.x * c.x + c.y * c.y;
    const double x = (a2 * (b.y - c.y) + b2 * (c.y - a.y) + c2 * (a.y - b.y)) / d;
    const double y = (a2 * (c.x - b.x) + b2 * (a.x - c.x) + c2 * (b.x - a.x)) / d;
    return {x, y, std::max({std::hypot(a.x - x, a.y - y), std::hypot(b.x - x, b.y - y), std::hypot(c.x - x, c.y - y)})};
}

// The smallest disk of points[0..i) with points i and j on its boundary.
Sample with_two(const std::vector<glm::dvec2>& p, std::size_t i, std::size_t j) {
    Sample d = diameter(p[i], p[j]);
    for (std::size_t k = 0; k < j; ++k)
        if (!holds(d, p[k])) d = circumcircle(p[i], p[j], p[k]);
    return d;
}

// The smallest disk of points[0..i] with point i on its boundary.
Sample with_one(const std::vector<glm::dvec2>& p, std::size_t i) {
    Sample d{p[i].x, p[i].y, 0};
    for (std::size_t j = 0; j < i; ++j)
        if (!holds(d, p[j])) d = with_two(p, i, j);
    return d;
}

}  // namespace

Sample enclosing_disk(const std::vector<glm::dvec2>& points) {
    if (points.empty()) return {};
    Sample d{points[0].x, points[0].y, 0};
    for (std::size_t i = 1; i < points.size(); ++i)
        if (!holds(d, points[i])) d = with_one(points, i);
    for (const glm::dvec2& p : points) d.r = std::max(d.r, std::hypot(p.x - d.x, p.y - d.y));
    return d;
}

}  // namespace mobb
