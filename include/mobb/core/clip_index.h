// A clip prepared once for the flat queries (the circle sweep, sweep.h, and the best scan, scan.h):
// float SoA samples, a root box and a time-implicit hierarchy of bounding circles. Built once per clip,
// queried under any placement.
#pragma once
#include <cstddef>
#include <vector>

#include "mobb/core/obb.h"
#include "mobb/core/path.h"

namespace mobb {

/// Bounding circles of one level's blocks as float columns (clip's local frame, metres; centre of
/// the block's positions' bounding rectangle, radius holding every sample disk, rounded outward).
/// The columns hold count + 8 entries: the padding is NaN, so 4-wide tests past the end stay in
/// bounds and never pass.
struct Circles {
    const float* x = nullptr;
    const float* y = nullptr;
    const float* r = nullptr;
    std::size_t count = 0;
};

/// Per-clip acceleration structure for collide_sweep() and collide_scan().
/// Level k of the hierarchy holds one circle per block of `kLeaf << k` consecutive samples
/// (block b covers samples [b * (kLeaf << k), (b + 1) * (kLeaf << k)) clipped to the path), so a
/// block's time range is implicit and its children at level k - 1 are blocks 2b and 2b + 1. The top
/// level has one block. The double samples stay in path() for the exact final test.
class ClipIndex {
public:
    static constexpr int kLeafShift = 4;
    static constexpr int kLeaf = 1 << kLeafShift;  ///< samples per leaf block

    /// Throws std::invalid_argument for an empty or invalid path (validate()), more than 2^21 samples
    /// (9.7 h at 60 Hz), or a coordinate or radius beyond 1e9 m (floats stay finite and exact enough
    /// for the conservative filters).
    static ClipIndex build(Path path);

    const Path& path() const { return path_; }
    std::size_t size() const { return path_.size(); }
    /// Root MOBB (paper 3.1, chord axis, conservative margin): the 1-level test of both queries.
    const Obb2& root_box() const { return root_; }
    /// Sample columns as float, padded with zeros to size() + 16 so blocks of 16 loads stay in bounds.
    const float* xs() const { return x_.data(); }
    const float* ys() const { return y_.data(); }
    const float* rs() const { return r_.data(); }
    int levels() const { return int(levels_.size()); }
    /// Level k's circles, 0 <= k < levels().
    Circles level(int k) const {
        const Columns& c = levels_[std::size_t(k)];
        return {c.x.data(), c.y.data(), c.r.data(), c.x.size() - 8};
    }
    /// Largest |x| + |y| of any sample (metres) and largest radius: scale for rounding margins.
    double max_abs() const { return max_abs_; }
    double max_radius() const { return max_r_; }

private:
    struct Columns {
        std::vector<float> x, y, r;
    };
    Path path_;
    Obb2 root_;
    std::vector<float> x_, y_, r_;
    std::vector<Columns> levels_;
    double max_abs_ = 0, max_r_ = 0;
};

}  // namespace mobb
