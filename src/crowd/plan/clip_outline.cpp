#include "plan/clip_outline.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "mobb/core/angle.h"

namespace mobb::crowd {

ClipOutline outline_of(const Path& path) {
    ClipOutline out;
    for (std::size_t i = 0; i < path.size(); i += ClipOutline::kBlock) {
        const std::size_t end = std::min(path.size(), i + ClipOutline::kBlock);
        double cx = 0, cy = 0, r = 0;
        for (std::size_t j = i; j < end; ++j) cx += path.samples[j].x, cy += path.samples[j].y;
        cx /= double(end - i), cy /= double(end - i);
        for (std::size_t j = i; j < end; ++j)
            r = std::max(r, std::hypot(path.samples[j].x - cx, path.samples[j].y - cy) + path.samples[j].r);
        out.blocks.push_back({cx, cy, r});
    }
    std::vector<std::array<double, 2>> pts;
    for (const Sample& s : path.samples) {
        pts.push_back({s.x, s.y});
        out.r_max = std::max(out.r_max, s.r);
    }
    std::sort(pts.begin(), pts.end());
    pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
    if (pts.size() < 3) {
        out.hull = pts;
        return out;
    }
    // Andrew's monotone chain: lower hull, then upper hull.
    auto cross = [](const auto& o, const auto& a, const auto& b) {
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
    };
    std::vector<std::array<double, 2>>& h = out.hull;
    for (int pass = 0; pass < 2; ++pass) {
        const std::size_t floor = h.size();
        for (const auto& q : pts) {
            while (h.size() >= floor + 2 && cross(h[h.size() - 2], h.back(), q) <= 0) h.pop_back();
            h.push_back(q);
        }
        h.pop_back();  // the next chain starts with it
        std::reverse(pts.begin(), pts.end());
    }
    for (int b = 0; b < ClipOutline::kBins; ++b) {
        const double angle = 2 * kPi * (b + 0.5) / ClipOutline::kBins, ux = std::cos(angle), uy = std::sin(angle);
        int best = 0;
        for (int i = 1; i < int(h.size()); ++i)
            if (ux * h[std::size_t(i)][0] + uy * h[std::size_t(i)][1] >
                ux * h[std::size_t(best)][0] + uy * h[std::size_t(best)][1])
                best = i;
        out.extreme.push_back(best);
    }
    return out;
}

std::vector<ClipOutline> outlines_of(const MotionGraph& g) {
    std::vector<ClipOutline> out;
    for (const GraphClip& c : g.clips) out.push_back(outline_of(c.path));
    return out;
}

namespace {

// How far a point is outside the world rectangle (0 inside), metres.
double excursion(double x, double y, const World& w) { return std::max({0.0, w.x0 - x, x - w.x1, w.y0 - y, y - w.y1}); }

// The largest u(v) over the hull's vertices v, each computed as u computes it, from vertex `start` on:
// along a convex polygon the exact values rise to one maximum and fall, and rounding moves them far
// less than the slack, so walking each way while they stay within the slack of the best meets every
// vertex whose computed value can be the largest. A good start (ClipOutline::extreme) takes a step or two.
template <class U>
double hull_max(const std::vector<std::array<double, 2>>& hull, int start, U&& u) {
    constexpr double kSlack = 1e-7;  // metres; rounding errs by ~1e-13 m at a kilometre
    const int n = int(hull.size());
    const std::array<double, 2>* h = hull.data();
    double best = u(h[start]);
    for (int i = start, left = n - 1; left > 0; --left) {  // forward
        i = i + 1 == n ? 0 : i + 1;
        const double v = u(h[i]);
        if (v < best - kSlack) break;
        best = std::max(best, v);
    }
    for (int i = start, left = n - 1; left > 0; --left) {  // backward
        i = i == 0 ? n - 1 : i - 1;
        const double v = u(h[i]);
        if (v < best - kSlack) break;
        best = std::max(best, v);
    }
    return best;
}

// The direction bin of angle a (ClipOutline::kBins over the turn, a power of two).
int bin_of(double a) {
    const double b = a * (ClipOutline::kBins / (2 * kPi));
    if (!(std::abs(b) < 1e9)) return 0;                    // any start is right, only slower
    const auto i = std::int64_t(b) - std::int64_t(b < 0);  // floor, but for whole negative b: a bin off
    return int(i & (ClipOutline::kBins - 1));
}

}  // namespace

// A candidate "leaves the world" when its root goes farther outside the rectangle than where it
// starts, so an agent pushed out by a fallback may walk back in.
PlacedCandidate place_clip(const ClipOutline& outline, int clip, std::int64_t frames, const Placement& p,
                           const Rigid2& m, std::int64_t frame, const World* world) {
    PlacedCandidate out{clip, p, {}, false, 0.0};
    out.box = {1e300, 1e300, -1e300, -1e300, frame, frame + frames};
    if (!world && outline.hull.size() >= 3 && outline.extreme.size() == std::size_t(ClipOutline::kBins)) {
        // Each side by a walk from the hull vertex farthest that way (x grows along the angle -theta in
        // the clip's frame, y along pi / 2 - theta, the minima half a turn on). Rigid2::apply_x rounds
        // x = (c vx - s vy) + tx, and adding tx keeps the order (rounding is monotonic): the side is the
        // extreme of c vx - s vy, plus tx, as the loop below finds it.
        const int b = bin_of(-p.theta), quarter = ClipOutline::kBins / 4;
        const auto& e = outline.extreme;
        const auto start = [&](int quarters) {
            return e[std::size_t((b + quarters * quarter) & (ClipOutline::kBins - 1))];
        };
        const double c = m.c, s = m.s;
        const auto& h = outline.hull;
        const double x1 = hull_max(h, start(0), [&](const auto& v) { return c * v[0] - s * v[1]; });
        const double x0 = -hull_max(h, start(2), [&](const auto& v) { return -(c * v[0] - s * v[1]); });
        const double y1 = hull_max(h, start(1), [&](const auto& v) { return s * v[0] + c * v[1]; });
        const double y0 = -hull_max(h, start(3), [&](const auto& v) { return -(s * v[0] + c * v[1]); });
        out.box.x0 = x0 + m.tx - outline.r_max;
        out.box.y0 = y0 + m.ty - outline.r_max;
        out.box.x1 = x1 + m.tx + outline.r_max;
        out.box.y1 = y1 + m.ty + outline.r_max;
        return out;
    }
    const double start = world ? excursion(p.x, p.y, *world) : 0.0;
    for (const auto& v : outline.hull) {
        const double x = m.apply_x(v[0], v[1]), y = m.apply_y(v[0], v[1]);
        out.box.x0 = std::min(out.box.x0, x);
        out.box.y0 = std::min(out.box.y0, y);
        out.box.x1 = std::max(out.box.x1, x);
        out.box.y1 = std::max(out.box.y1, y);
        if (world) out.excess = std::max(out.excess, excursion(x, y, *world) - start);
    }
    out.box.x0 -= outline.r_max;
    out.box.y0 -= outline.r_max;
    out.box.x1 += outline.r_max;
    out.box.y1 += outline.r_max;
    out.leaves_world = out.excess > 0;
    return out;
}

}  // namespace mobb::crowd
