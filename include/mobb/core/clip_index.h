// A clip prepared once for the fast queries (fast_query.h, scan.h): float SoA samples, a root box and
// a time-implicit hierarchy of motion tubes. Built once per clip, queried under any placement.
#pragma once
#include <cstddef>
#include <vector>

#include "mobb/core/obb.h"
#include "mobb/core/path.h"

namespace mobb {

/// A block's motion as a straight line in time, with a tube around it (clip's local frame, float):
/// sample i of the block lies at (x, y) + (i - m) (vx, vy) within distance r - r_i, where m is the
/// block's middle sample index (first + last) / 2. So every sample disk lies inside the tube, and two
/// time-aligned blocks can only collide where their lines come closer than the sum of the tubes' r.
/// Metres and metres per sample; r rounded outward; `speed` = |(vx, vy)| rounded up. The block also
/// has a bounding circle (cx, cy, cr), centred on its positions' bounding rectangle, rounded outward:
/// the cheaper test where motion does not help.
struct Tube {
    float x = 0, y = 0, vx = 0, vy = 0, r = 0, speed = 0;
    float cx = 0, cy = 0, cr = 0;
};

/// Per-clip acceleration structure for collide_fast() and collide_scan().
/// Level k of the hierarchy holds one tube per block of `kLeaf << k` consecutive samples
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
    const std::vector<Tube>& level(int k) const { return levels_[std::size_t(k)]; }
    /// Largest |x| + |y| of any sample (metres) and largest radius: scale for rounding margins.
    double max_abs() const { return max_abs_; }
    double max_radius() const { return max_r_; }

private:
    Path path_;
    Obb2 root_;
    std::vector<float> x_, y_, r_;
    std::vector<std::vector<Tube>> levels_;
    double max_abs_ = 0, max_r_ = 0;
};

}  // namespace mobb
