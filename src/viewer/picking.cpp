#include "picking.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "box_layer.h"

namespace mobb::viewer {

namespace {

/// Entry distance of a ray into a vertical cylinder (GL world: axis along y, base at y0, height h).
double enter_cylinder(const render::Ray& ray, double cx, double cz, double r, double y0, double h) {
    const double ox = ray.origin.x - cx, oz = ray.origin.z - cz, dx = ray.dir.x, dz = ray.dir.z;
    const double a = dx * dx + dz * dz, b = 2 * (ox * dx + oz * dz), c = ox * ox + oz * oz - r * r;
    double best = std::numeric_limits<double>::infinity();
    if (a > 1e-12) {
        const double disc = b * b - 4 * a * c;
        if (disc >= 0) {
            const double t = (-b - std::sqrt(disc)) / (2 * a);
            const double y = ray.origin.y + t * ray.dir.y;
            if (t > 0 && y >= y0 && y <= y0 + h) best = t;
        }
    }
    // Caps: the top or bottom disk.
    if (std::fabs(ray.dir.y) > 1e-12) {
        for (double yc : {y0, y0 + h}) {
            const double t = (yc - ray.origin.y) / ray.dir.y;
            const double px = ox + t * dx, pz = oz + t * dz;
            if (t > 0 && px * px + pz * pz <= r * r) best = std::min(best, t);
        }
    }
    return best;
}

}  // namespace

Pick pick_disk(const State& s, const render::Ray& ray, double* distance) {
    Pick best;
    double nearest = std::numeric_limits<double>::infinity();
    const double ts = s.scene.time_scale;
    for (std::size_t k = 0; k < s.clips.size(); ++k) {
        if (k < s.scene.clips.size() && !s.scene.clips[k].visible) continue;
        const Path& path = s.clips[k].tree->path();
        const Rigid2 m = Rigid2::of(s.places[k]);
        for (std::size_t i = 0; i < path.size(); ++i) {
            const Sample& smp = path.samples[i];
            const double t0 = sample_time(s.places[k], path.dt, std::int64_t(i));
            const double d =
                enter_cylinder(ray, m.apply_x(smp.x, smp.y), -m.apply_y(smp.x, smp.y), smp.r, t0 * ts, path.dt * ts);
            if (d < nearest) {
                nearest = d;
                best = {int(k), int(i)};
            }
        }
    }
    if (distance) *distance = nearest;
    return best;
}

namespace {

/// Entry parameter of a ray (space-time origin and direction) into a box, infinity when it misses.
double enter_box(const Obb3& box, const glm::dvec3& origin, const glm::dvec3& dir) {
    const glm::dvec3 o = glm::transpose(box.axes) * (origin - box.center), d = glm::transpose(box.axes) * dir;
    double lo = 0, hi = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i) {
        if (std::fabs(d[i]) < 1e-12) {
            if (std::fabs(o[i]) > box.half[i]) return std::numeric_limits<double>::infinity();
            continue;
        }
        double a = (-box.half[i] - o[i]) / d[i], b = (box.half[i] - o[i]) / d[i];
        if (a > b) std::swap(a, b);
        lo = std::max(lo, a), hi = std::min(hi, b);
        if (lo > hi) return std::numeric_limits<double>::infinity();
    }
    return lo;
}

}  // namespace

BoxPick pick_box(const State& s, const render::Ray& ray) {
    BoxPick best;
    best.distance = std::numeric_limits<double>::infinity();
    const render::Layers& l = s.scene.layers;
    if (!l.boxes || !s.queried) return best;
    // The ray in space-time: GL (x, t * scale, -y) back to (x, y, t); the ray parameter is unchanged.
    const double ts = s.scene.time_scale;
    const glm::dvec3 origin(ray.origin.x, -ray.origin.z, ray.origin.y / ts), dir(ray.dir.x, -ray.dir.z, ray.dir.y / ts);
    for (int clip : {s.scene.query_a, s.scene.query_b}) {
        const Tree& tree = *s.clips[std::size_t(clip)].tree;
        const SpaceTimeRigid m = SpaceTimeRigid::of(s.places[std::size_t(clip)]);
        for (std::size_t n = 0; n < tree.nodes().size(); ++n) {
            const Node& node = tree.nodes()[n];
            if (!l.all_levels && !render::shown_at_level(node, l.level, l.levels)) continue;
            const double d = enter_box(transformed(tree.box3(node), m), origin, dir);
            if (d < best.distance) best = {clip, std::int32_t(n), d};
        }
    }
    return best;
}

std::optional<DiskInfo> disk_of(const State& s, const Pick& p) {
    if (p.clip < 0 || p.clip >= int(s.clips.size())) return std::nullopt;
    const Path& path = s.clips[std::size_t(p.clip)].tree->path();
    if (p.sample < 0 || p.sample >= int(path.size())) return std::nullopt;
    const Placement& place = s.places[std::size_t(p.clip)];
    const Sample& smp = path.samples[std::size_t(p.sample)];
    const Rigid2 m = Rigid2::of(place);
    return DiskInfo{{m.apply_x(smp.x, smp.y), m.apply_y(smp.x, smp.y)},
                    sample_time(place, path.dt, p.sample),
                    sample_time(place, path.dt, p.sample + 1),
                    smp.r};
}

std::optional<Ruler> measure(const State& s, const Pick& a, const Pick& b) {
    const auto da = disk_of(s, a), db = disk_of(s, b);
    if (!da || !db) return std::nullopt;
    Ruler r;
    r.distance = glm::length(da->centre - db->centre);
    r.time_gap = std::max({0.0, db->t0 - da->t1, da->t0 - db->t1});
    r.radii = da->r + db->r;
    r.clearance = r.distance - r.radii;
    return r;
}

std::optional<glm::dvec2> ground_point(const render::Ray& ray, double height) {
    if (std::fabs(ray.dir.y) < 1e-9) return std::nullopt;
    const double t = (height - ray.origin.y) / ray.dir.y;
    if (t <= 0) return std::nullopt;
    return glm::dvec2(ray.origin.x + t * ray.dir.x, -(ray.origin.z + t * ray.dir.z));
}

}  // namespace mobb::viewer
