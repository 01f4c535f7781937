// Points near a place, in their own order: a grid of cells a little wider than `reach`, each with a bit
// per point, so that the points within `reach` of a place are among those of the 3 x 3 cells around it.
// The goal policy adds up its crowding cost over the neighbours near each end a search scores, in the
// order of a loop over them all, so the sum is the same to the bit.
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
        if (nx_ == 0) {  // no grid: all of them
            for (std::size_t i = 0; i < points_.size(); ++i) f(i);
            return;
        }
        const double fx = (x - x0_) / cell_, fy = (y - y0_) / cell_;
        if (!(fx >= -1 && fx < nx_ + 1 && fy >= -1 && fy < ny_ + 1)) return;  // more than a cell off the grid
        const int ix = int(std::floor(fx)), iy = int(std::floor(fy));
        const int x0 = ix > 0 ? ix - 1 : 0, x1 = ix + 1 < nx_ ? ix + 1 : nx_ - 1;
        const int y0 = iy > 0 ? iy - 1 : 0, y1 = iy + 1 < ny_ ? iy + 1 : ny_ - 1;
        for (std::size_t w = 0; w < words_; ++w) {
            std::uint64_t m = 0;
            for (int jx = x0; jx <= x1; ++jx)
                for (int jy = y0; jy <= y1; ++jy) m |= bits_[cell(jx, jy) * words_ + w];
            for (; m; m &= m - 1) f(w * 64 + std::size_t(__builtin_ctzll(m)));
        }
    }

private:
    std::size_t cell(int ix, int iy) const { return std::size_t(ix) * std::size_t(ny_) + std::size_t(iy); }

    std::vector<std::array<double, 2>> points_;
    double x0_ = 0, y0_ = 0, cell_ = 1;
    int nx_ = 0, ny_ = 0;              // 0: no grid
    std::size_t words_ = 0;            // per cell
    std::vector<std::uint64_t> bits_;  // [cell * words_ + i / 64], bit i % 64: point i lies in the cell
};

}  // namespace mobb::crowd
