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

// Bounding circle of samples [first, end), centred on their positions' bounding rectangle.
void bound_circle(const Path& path, std::size_t first, std::size_t end, float& cx, float& cy, float& cr) {
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    for (std::size_t i = first; i < end; ++i) {
        const Sample& s = path.samples[i];
        x0 = std::min(x0, s.x), x1 = std::max(x1, s.x);
        y0 = std::min(y0, s.y), y1 = std::max(y1, s.y);
    }
    cx = float(0.5 * (x0 + x1));
    cy = float(0.5 * (y0 + y1));
    double r = 0;
    for (std::size_t i = first; i < end; ++i) {
        const Sample& s = path.samples[i];
        r = std::max(r, std::hypot(s.x - double(cx), s.y - double(cy)) + s.r);
    }
    cr = round_up(r * (1 + 1e-12));
}

}  // namespace

ClipIndex ClipIndex::build(Path path) {
    validate(path);
    if (path.samples.empty()) throw std::invalid_argument("clip index: the path has no samples");
    // More than any motion clip needs: refused rather than tested.
    if (path.samples.size() > (std::size_t(1) << 21)) throw std::invalid_argument("clip index: more than 2^21 samples");
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
        const std::size_t count = (n + block - 1) / block;
        Columns level{std::vector<float>(count + 8, NAN), std::vector<float>(count + 8, NAN),
                      std::vector<float>(count + 8, NAN)};
        for (std::size_t k = 0; k < count; ++k)
            bound_circle(path, k * block, std::min(n, (k + 1) * block), level.x[k], level.y[k], level.r[k]);
        c.levels_.push_back(std::move(level));
        if (block >= n) break;
    }
    c.root_ = fit_obb2(path, 0, n);
    c.path_ = std::move(path);
    return c;
}

}  // namespace mobb
