// A clip prepared once for the flat queries (the circle sweep, sweep.h, and the best scan, scan.h):
// float SoA samples, a root box and a time-implicit hierarchy of bounding circles. Built once per clip,
// queried under any placement.
#pragma once
#include <cstddef>
#include <memory>
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
    std::size_t size() const { return size_; }
    /// Root MOBB (paper 3.1, chord axis, conservative margin): the 1-level test of both queries.
    const Obb2& root_box() const { return root_; }
    /// Sample columns as float, padded with zeros to size() + 16 so blocks of 16 loads stay in bounds.
    const float* xs() const { return samples_.x; }
    const float* ys() const { return samples_.y; }
    const float* rs() const { return samples_.r; }
    int levels() const { return int(levels_.size()); }
    /// Level k's circles, 0 <= k < levels(); 8 NaN entries follow the last.
    Circles level(int k) const { return levels_[std::size_t(k)]; }
    /// Sliding windows for time-aligned tests against another clip's aligned blocks of s = 1 << shift
    /// samples (shift 0: single samples; kLeafShift; kLeafShift + 1). Window g of phase p,
    /// 0 <= p < s, holds samples [s g + p - 1, s g + p + s + 1) clipped to the path: for a block
    /// [s k, s k + s) of the other clip whose time-aligned partners lie on diagonals j - i in
    /// [m - 1, m + 1], m = s G + p, they all lie in window k + G. Entry g + 1 holds window g, for
    /// g = -1 .. size() / s + 1; windows without samples are NaN, and so are the padding entries
    /// that follow (16 for shift 0, so blocks of 16 loads stay in bounds; 4 otherwise).
    Circles windows(int shift, int phase) const {
        const Windows& w = windows_[shift == 0 ? 0 : shift - kLeafShift + 1];
        const float* x = w.x + std::size_t(phase) * 3 * w.stride;
        return {x, x + w.stride, x + 2 * w.stride, w.count};
    }
    /// Largest |x| + |y| of any sample (metres) and largest radius: scale for rounding margins.
    double max_abs() const { return max_abs_; }
    double max_radius() const { return max_r_; }
    /// max_abs() + max_radius().
    double reach() const { return reach_; }

private:
    // The windows of one shift: phase p's columns x, y, r (each `stride` floats long) at
    // x + 3 p stride.
    struct Windows {
        const float* x = nullptr;
        std::size_t stride = 0, count = 0;
    };
    Path path_;
    Obb2 root_;
    // Every float column in one allocation, never changed after build(): copies share it, so the
    // columns' pointers below stay valid in every copy.
    std::shared_ptr<const std::vector<float>> floats_;
    Circles samples_;
    std::vector<Circles> levels_;
    static constexpr int kWindowShifts = 3;  // 0, kLeafShift, kLeafShift + 1
    Windows windows_[kWindowShifts];
    std::size_t size_ = 0;
    double max_abs_ = 0, max_r_ = 0, reach_ = 0;
};

}  // namespace mobb
