// Points near a place, in their own order: a grid of cells a little wider than reach / kSplit, each with
// a bit per point, and for each cell the union of the bits of the cells within kSplit of it (a block of
// 2 kSplit + 1 cells a side), so that the points within `reach` of a place are among those of its cell's
// block, read as one mask. The goal policy adds up its crowding cost over the neighbours near each end a
// search scores, in the order of a loop over them all, so the sum is the same to the bit.
#pragma once
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace mobb::crowd {

class NearPoints {
public:
    NearPoints() = default;
    NearPoints(std::vector<std::array<double, 2>> points, double reach);

    const std::vector<std::array<double, 2>>& points() const { return points_; }

    /// Calls f(i) for points i in ascending order: every point within `reach` of (x, y) (strictly), and
    /// some farther.
    template <class F>
    void near(double x, double y, F&& f) const {
        if (words_ == 0) {  // no grid: all of them
            for (std::size_t i = 0; i < points_.size(); ++i) f(i);
            return;
        }
        // The block grid has kSplit cells more each side than the points' grid: a place farther off has
        // no point within reach. For fx >= -kSplit, int(fx + kSplit) is floor(fx) + kSplit (truncation of
        // a non-negative number) but where fx + kSplit rounds up to a whole number: a place on a cell's
        // edge to 1e-16 of a cell, whose points within reach lie in the blocks of the cells either side.
        const double fx = (x - x0_) / cell_ + kSplit, fy = (y - y0_) / cell_ + kSplit;
        if (!(fx >= 0 && fx < bx_ && fy >= 0 && fy < by_)) return;
        const std::uint64_t* m = &blocks_[(std::size_t(fx) * std::size_t(by_) + std::size_t(fy)) * words_];
        for (std::size_t w = 0; w < words_; ++w)
            for (std::uint64_t b = m[w]; b; b &= b - 1) f(w * 64 + std::size_t(__builtin_ctzll(b)));
    }

    /// Grid cells per reach: finer cells list fewer points farther than reach, for (2 kSplit + 1)^2 bits set
    /// per point at construction. 3: the first 3 s of SteerSuite's bottleneck-squeeze ran 9.87 G instructions,
    /// against 10.41 G at 1, 9.98 G at 2, 9.85 G at 4 (bench/results/log.md, "fourth stop").
    static constexpr int kSplit = 3;

private:
    std::vector<std::array<double, 2>> points_;
    double x0_ = 0, y0_ = 0, cell_ = 1;
    double bx_ = 0, by_ = 0;             // the block grid's cells along x and y (doubles: compared with doubles)
    std::size_t words_ = 0;              // per cell; 0: no grid
    std::vector<std::uint64_t> blocks_;  // [cell * words_ + i / 64], bit i % 64: point i lies in the cell's block
};

}  // namespace mobb::crowd
