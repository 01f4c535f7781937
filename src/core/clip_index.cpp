#include "mobb/core/clip_index.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "mobb/core/fit.h"

namespace mobb {

namespace {

constexpr double kMaxCoordinate = 1e9;  // metres; keeps every float finite

// Smallest float not below v (v >= 0): outward rounding of radii.
float round_up(double v) {
    float f = float(v);
    if (double(f) < v) f = std::nextafter(f, INFINITY);
    return f;
}

// Tube of samples [first, end): velocity along the chord from first to last sample (the MOBB
// axis, paper 3.1), line through the centre of the residuals' bounding rectangle; both stored as
// float, then the radius measured in double from the float line and rounded up.
Tube bound(const Path& path, std::size_t first, std::size_t end, bool moving) {
    const std::size_t last = end - 1;
    const double m = 0.5 * double(first + last);
    const Sample& s0 = path.samples[first];
    const Sample& s1 = path.samples[last];
    Tube t;
    if (moving && last > first) {
        t.vx = float((s1.x - s0.x) / double(last - first));
        t.vy = float((s1.y - s0.y) / double(last - first));
    }
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    for (std::size_t i = first; i < end; ++i) {
        const Sample& s = path.samples[i];
        const double k = double(i) - m;
        x0 = std::min(x0, s.x - double(t.vx) * k), x1 = std::max(x1, s.x - double(t.vx) * k);
        y0 = std::min(y0, s.y - double(t.vy) * k), y1 = std::max(y1, s.y - double(t.vy) * k);
    }
    t.x = float(0.5 * (x0 + x1));
    t.y = float(0.5 * (y0 + y1));
    double r = 0;
    for (std::size_t i = first; i < end; ++i) {
        const Sample& s = path.samples[i];
        const double k = double(i) - m;
        r = std::max(r, std::hypot(s.x - double(t.x) - double(t.vx) * k, s.y - double(t.y) - double(t.vy) * k) + s.r);
    }
    t.r = round_up(r * (1 + 1e-12));
    t.speed = round_up(std::hypot(double(t.vx), double(t.vy)) * (1 + 1e-12));
    return t;
}

// The thinner of the chord tube and the standing one (a circle): a turning block is often rounder.
Tube bound(const Path& path, std::size_t first, std::size_t end) {
    const Tube moving = bound(path, first, end, true), still = bound(path, first, end, false);
    Tube t = moving.r <= still.r ? moving : still;
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    for (std::size_t i = first; i < end; ++i) {
        const Sample& s = path.samples[i];
        x0 = std::min(x0, s.x), x1 = std::max(x1, s.x);
        y0 = std::min(y0, s.y), y1 = std::max(y1, s.y);
    }
    t.cx = float(0.5 * (x0 + x1));
    t.cy = float(0.5 * (y0 + y1));
    double r = 0;
    for (std::size_t i = first; i < end; ++i) {
        const Sample& s = path.samples[i];
        r = std::max(r, std::hypot(s.x - double(t.cx), s.y - double(t.cy)) + s.r);
    }
    t.cr = round_up(r * (1 + 1e-12));
    return t;
}

}  // namespace

ClipIndex ClipIndex::build(Path path) {
    validate(path);
    if (path.samples.empty()) throw std::invalid_argument("clip index: the path has no samples");
    // Sample offsets stay exact in float (half-integers below 2^22) in the tube tests.
    if (path.samples.size() > (std::size_t(1) << 21))
        throw std::invalid_argument("clip index: more than 2^21 samples");
    ClipIndex c;
    for (const Sample& s : path.samples) {
        if (std::abs(s.x) > kMaxCoordinate || std::abs(s.y) > kMaxCoordinate || s.r > kMaxCoordinate)
            throw std::invalid_argument("clip index: a coordinate or radius exceeds 1e9 m");
        c.max_abs_ = std::max(c.max_abs_, std::abs(s.x) + std::abs(s.y));
        c.max_r_ = std::max(c.max_r_, s.r);
    }
    const std::size_t n = path.size();
    c.x_.assign(n + 16, 0.0f);
    c.y_.assign(n + 16, 0.0f);
    c.r_.assign(n + 16, 0.0f);
    for (std::size_t i = 0; i < n; ++i) {
        c.x_[i] = float(path.samples[i].x);
        c.y_[i] = float(path.samples[i].y);
        c.r_[i] = float(path.samples[i].r);
    }
    for (std::size_t block = std::size_t(kLeaf);; block *= 2) {
        std::vector<Tube> level;
        for (std::size_t f = 0; f < n; f += block) level.push_back(bound(path, f, std::min(n, f + block)));
        c.levels_.push_back(std::move(level));
        if (block >= n) break;
    }
    c.root_ = fit_obb2(path, 0, n);
    c.path_ = std::move(path);
    return c;
}

}  // namespace mobb
