#include "disk_lod.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mobb::render {

int disk_lod(double sample_pixels, std::size_t scene_disks) {
    if (scene_disks <= kDiskLodAbove || !(sample_pixels >= 0)) return 1;
    int k = 1;
    while (k < kDiskLodMaxK && 2.0 * k * sample_pixels <= kDiskLodPixels) k *= 2;
    return k;
}

double nearest_pixels_per_metre(const glm::mat4& view_proj, int height, const glm::vec3& lo, const glm::vec3& hi) {
    // Clip y is the projection's y scale times view-space y, clip w the view depth: a metre across
    // the view at depth w spans |row y| / w of the half-height (view rows are unit vectors).
    const glm::vec3 row_y(view_proj[0][1], view_proj[1][1], view_proj[2][1]);
    double nearest = std::numeric_limits<double>::infinity();
    for (int c = 0; c < 8; ++c) {
        const glm::vec3 p((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z);
        const double w = double(view_proj[0][3]) * p.x + double(view_proj[1][3]) * p.y + double(view_proj[2][3]) * p.z +
                         double(view_proj[3][3]);
        nearest = std::min(nearest, w);
    }
    if (!(nearest > 1e-6)) return std::numeric_limits<double>::infinity();
    return double(glm::length(row_y)) * 0.5 * double(height) / nearest;
}

Bounds path_bounds(const Path& path, const Placement& place) {
    Bounds b;
    if (path.samples.empty()) return b;
    const Rigid2 m = Rigid2::of(place);
    const double t1 = sample_time(place, path.dt, std::int64_t(path.size()));
    for (const Sample& s : path.samples) {
        const double x = m.apply_x(s.x, s.y), y = m.apply_y(s.x, s.y);
        b.add({x - s.r, y - s.r, place.t0});
        b.add({x + s.r, y + s.r, t1});
    }
    return b;
}

std::vector<Bounds> chunk_bounds(const Path& path, const Placement& place) {
    const Rigid2 m = Rigid2::of(place);
    std::vector<Bounds> out;
    const std::size_t n = path.size(), step = std::size_t(kDiskChunk);
    for (std::size_t c0 = 0; c0 < n; c0 += step) {
        const std::size_t c1 = std::min(n, c0 + step);
        Bounds b;
        for (std::size_t i = c0; i < c1; ++i) {
            const Sample& s = path.samples[i];
            const double x = m.apply_x(s.x, s.y), y = m.apply_y(s.x, s.y);
            b.add({x - s.r, y - s.r, sample_time(place, path.dt, std::int64_t(c0))});
            b.add({x + s.r, y + s.r, sample_time(place, path.dt, std::int64_t(c1))});
        }
        out.push_back(b);
    }
    return out;
}

bool outside_view(const glm::mat4& view_proj, const glm::vec3& lo, const glm::vec3& hi) {
    int left = 0, right = 0, below = 0, above = 0, behind = 0, beyond = 0;
    for (int c = 0; c < 8; ++c) {
        const glm::vec4 p =
            view_proj * glm::vec4((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z, 1.0f);
        left += p.x<-p.w, right += p.x> p.w, below += p.y<-p.w, above += p.y> p.w;
        behind += p.z<-p.w, beyond += p.z> p.w;
    }
    return left == 8 || right == 8 || below == 8 || above == 8 || behind == 8 || beyond == 8;
}

int clip_lod(const Bounds& bounds, double dt, double time_scale, std::size_t scene_disks, const glm::mat4& view_proj,
             int height) {
    if (bounds.empty || scene_disks <= kDiskLodAbove) return 1;
    const glm::vec3 a = to_gl(bounds.lo.x, bounds.lo.y, bounds.lo.z, time_scale);
    const glm::vec3 b = to_gl(bounds.hi.x, bounds.hi.y, bounds.hi.z, time_scale);
    const double ppm = nearest_pixels_per_metre(view_proj, height, glm::min(a, b), glm::max(a, b));
    return disk_lod(dt * std::fabs(time_scale) * ppm, scene_disks);
}

std::vector<int> frame_lods(const Frame& frame, const glm::mat4& view_proj, int height) {
    std::size_t total = 0;
    for (const ClipView& clip : frame.clips) total += clip.tree->path().size();
    std::vector<int> out;
    for (const ClipView& clip : frame.clips) {
        const Path& path = clip.tree->path();
        out.push_back(clip_lod(path_bounds(path, clip.place), path.dt, frame.time_scale, total, view_proj, height));
    }
    return out;
}

std::vector<DiskInstance> disk_instances(const Path& path, const Placement& place) {
    const Rigid2 m = Rigid2::of(place);
    std::vector<DiskInstance> out;
    out.reserve(path.size());
    for (std::size_t i = 0; i < path.size(); ++i) {
        const Sample& s = path.samples[i];
        out.emplace_back(float(m.apply_x(s.x, s.y)), float(m.apply_y(s.x, s.y)),
                         float(sample_time(place, path.dt, std::int64_t(i))), float(s.r));
    }
    return out;
}

std::vector<DiskGroup> group_disks(const std::vector<DiskInstance>& disks, int k) {
    std::vector<DiskGroup> out;
    if (k < 1) k = 1;
    const std::size_t n = disks.size(), step = std::size_t(k);
    out.reserve((n + step - 1) / step);
    for (std::size_t i = 0; i < n; i += step) {
        const std::size_t j = std::min(i + step, n);
        const glm::dvec2 c0(disks[i].x, disks[i].y);
        // The axis ends where the next group starts; the last group ends on its own last disk.
        const glm::dvec2 c1 = j < n ? glm::dvec2(disks[j].x, disks[j].y) : glm::dvec2(disks[n - 1].x, disks[n - 1].y);
        const double m = double(j - i);
        double radius = 0;
        for (std::size_t q = i; q < j; ++q) {
            const glm::dvec2 c(disks[q].x, disks[q].y);
            const double u = double(q - i);
            const glm::dvec2 a = c0 + (c1 - c0) * (u / m), b = c0 + (c1 - c0) * ((u + 1) / m);
            radius = std::max(radius, double(disks[q].w) + std::max(glm::length(c - a), glm::length(c - b)));
        }
        // Round up so the float radius never falls below the exact bound.
        const float r = std::nextafter(float(radius), std::numeric_limits<float>::infinity());
        out.push_back({glm::vec4(disks[i].x, disks[i].y, disks[i].z, r),
                       glm::vec4(float(c1.x - c0.x), float(c1.y - c0.y), 0.0f, float(m))});
    }
    // A chunk's last cap is kept: the next chunk may be drawn at another level of detail, or not at all.
    for (std::size_t g = 0; g + 1 < out.size(); ++g)
        if ((g + 1) * step % std::size_t(kDiskChunk) != 0 && out[g + 1].base.w >= out[g].base.w) out[g].shift.z = 1.0f;
    return out;
}

TubeMesh tube_mesh(const std::vector<DiskGroup>& groups, double dt, int segments) {
    TubeMesh m;
    m.groups = groups.size();
    m.segments = segments;
    if (groups.empty() || segments < 3) return m;
    const std::size_t n = groups.size(), s = std::size_t(segments);
    const float two_pi = 6.28318530718f;
    // Ring j: centre, time, radius; the slope of group j's side along each direction comes from the
    // move of the centre and the change of radius between its rings.
    std::vector<glm::vec2> centre(n + 1);
    std::vector<float> time(n + 1), radius(n + 1);
    for (std::size_t j = 0; j < n; ++j) {
        centre[j] = glm::vec2(groups[j].base);
        time[j] = groups[j].base.z;
        radius[j] = std::max(groups[j].base.w, j > 0 ? groups[j - 1].base.w : 0.0f);
    }
    const DiskGroup& last = groups[n - 1];
    centre[n] = glm::vec2(last.base) + glm::vec2(last.shift);
    time[n] = last.base.z + float(dt * double(last.shift.w));
    radius[n] = last.base.w;
    const auto slope = [&](std::size_t g, const glm::vec2& d) {
        const float span = std::max(time[g + 1] - time[g], 1e-9f);
        return (glm::dot(d, centre[g + 1] - centre[g]) + radius[g + 1] - radius[g]) / span;
    };
    for (std::size_t j = 0; j <= n; ++j)
        for (std::size_t k = 0; k < s; ++k) {
            const float a = two_pi * float(k) / float(s);
            const glm::vec2 d(std::cos(a), std::sin(a)), p = centre[j] + radius[j] * d;
            // Each ring's normal is the mean of the sides above and below it: the tube is shaded smooth.
            const float m_below = slope(j > 0 ? j - 1 : 0, d), m_above = slope(j < n ? j : n - 1, d);
            m.vertices.push_back({glm::vec3(p, time[j]), glm::vec4(d, 0.5f * (m_below + m_above), 0.0f)});
        }
    const auto cap = [&](std::size_t ring, float up) {
        const auto first = std::uint32_t(m.vertices.size());
        for (std::size_t k = 0; k < s; ++k)
            m.vertices.push_back({m.vertices[ring * s + k].pos, glm::vec4(0.0f, 0.0f, 0.0f, up)});
        for (std::uint32_t k = 1; k + 1 < s; ++k)
            if (up > 0)
                m.indices.insert(m.indices.end(), {first, first + k, first + k + 1});
            else
                m.indices.insert(m.indices.end(), {first, first + k + 1, first + k});
    };
    cap(0, -1.0f);
    for (std::size_t g = 0; g < n; ++g)
        for (std::size_t k = 0; k < s; ++k) {
            const auto b0 = std::uint32_t(g * s + k), b1 = std::uint32_t(g * s + (k + 1) % s);
            const auto t0 = std::uint32_t(b0 + s), t1 = std::uint32_t(b1 + s);
            // Outward (counter-clockwise) like the unit cylinder's sides; the last vertex of each
            // triangle, GL's provoking one, on the group's own bottom ring.
            m.indices.insert(m.indices.end(), {t1, b0, b1, t1, t0, b0});
        }
    cap(n, 1.0f);
    return m;
}

std::vector<float> group_values(const std::vector<float>& values, int k, bool least) {
    std::vector<float> out;
    const std::size_t n = values.size(), step = std::size_t(std::max(k, 1));
    out.reserve((n + step - 1) / step);
    for (std::size_t i = 0; i < n; i += step) {
        const std::size_t j = std::min(i + step, n);
        double v = least ? double(values[i]) : 0.0;
        for (std::size_t q = i; q < j; ++q) v = least ? std::min(v, double(values[q])) : v + double(values[q]);
        out.push_back(float(least ? v : v / double(j - i)));
    }
    return out;
}

}  // namespace mobb::render
