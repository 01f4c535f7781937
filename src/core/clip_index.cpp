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

// Three float columns x, y, r of `count` entries and padding, each `stride` long, at `offset`.
struct Columns {
    std::size_t offset = 0, stride = 0, count = 0;
};

// Lays out every column of an index in one vector.
struct ColumnWriter {
    std::vector<float> floats;

    Columns add(std::size_t count, std::size_t padding, float fill) {
        const Columns c{floats.size(), count + padding, count};
        floats.resize(floats.size() + 3 * c.stride, fill);
        return c;
    }
    void set(const Columns& c, std::size_t k, float x, float y, float r) {
        float* p = floats.data() + c.offset + k;
        p[0] = x, p[c.stride] = y, p[2 * c.stride] = r;
    }
    // Entry k: the bounding circle of samples [first, end) clipped to the path; left as filled when
    // none is inside.
    void bound(const Columns& c, std::size_t k, const Path& path, std::int64_t first, std::int64_t end) {
        const auto f = std::size_t(std::max<std::int64_t>(0, first));
        const auto l = std::size_t(std::clamp<std::int64_t>(end, 0, std::int64_t(path.size())));
        float* p = floats.data() + c.offset + k;
        if (f < l) bound_circle(path, f, l, p[0], p[c.stride], p[2 * c.stride]);
    }
    static Circles circles(const std::vector<float>& v, const Columns& c) {
        const float* x = v.data() + c.offset;
        return {x, x + c.stride, x + 2 * c.stride, c.count};
    }
};

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
    ColumnWriter w;
    const Columns samples = w.add(n, 16, 0.0f);
    for (std::size_t i = 0; i < n; ++i)
        w.set(samples, i, float(path.samples[i].x), float(path.samples[i].y), float(path.samples[i].r));
    std::vector<Columns> levels;
    Columns windows[kWindowShifts];  // phase 0 of each shift; the other phases follow it
    for (std::size_t block = std::size_t(kLeaf);; block *= 2) {
        const std::size_t count = (n + block - 1) / block;
        levels.push_back(w.add(count, 8, NAN));
        for (std::size_t k = 0; k < count; ++k)
            w.bound(levels.back(), k, path, std::int64_t(k * block), std::int64_t((k + 1) * block));
        if (block >= n) break;
    }
    for (int k = 0; k < kWindowShifts; ++k) {
        const int shift = k == 0 ? 0 : kLeafShift + k - 1;
        const auto s = std::int64_t(1) << shift;
        const std::size_t count = std::size_t(std::int64_t(n) / s + 3);
        for (std::int64_t p = 0; p < s; ++p) {
            const Columns phase = w.add(count, shift == 0 ? 16 : 4, NAN);
            if (p == 0) windows[k] = phase;
            for (std::size_t e = 0; e < count; ++e) {
                const std::int64_t first = (std::int64_t(e) - 1) * s + p - 1;
                w.bound(phase, e, path, first, first + s + 2);
            }
        }
    }
    const auto floats = std::make_shared<const std::vector<float>>(std::move(w.floats));
    c.samples_ = w.circles(*floats, samples);
    for (const Columns& l : levels) c.levels_.push_back(w.circles(*floats, l));
    for (int k = 0; k < kWindowShifts; ++k)
        c.windows_[k] = {floats->data() + windows[k].offset, windows[k].stride, windows[k].count};
    c.floats_ = floats;
    c.root_ = fit_obb2(path, 0, n);
    c.size_ = n;
    c.reach_ = c.max_abs_ + c.max_r_;
    c.path_ = std::move(path);
    return c;
}

}  // namespace mobb
