#include "policy/near_points.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace mobb::crowd {

namespace {
// Cells a hundredth wider than the reach: two points within it lie in the same or adjacent cells, the
// rounding of their cell coordinates (about 1e-14 of a cell) notwithstanding.
constexpr double kWider = 1.01;
constexpr int kMaxCells = 4096;  // beyond (points spread far, or a reach near 0): no grid
}  // namespace

NearPoints::NearPoints(std::vector<std::array<double, 2>> points, double reach) : points_(std::move(points)) {
    if (points_.empty() || !(reach > 0)) return;  // a reach <= 0: no grid, the caller tests them all
    double x1 = points_[0][0], y1 = points_[0][1];
    x0_ = x1, y0_ = y1;
    for (const auto& p : points_) {
        if (!std::isfinite(p[0]) || !std::isfinite(p[1])) return;
        x0_ = std::min(x0_, p[0]), x1 = std::max(x1, p[0]);
        y0_ = std::min(y0_, p[1]), y1 = std::max(y1, p[1]);
    }
    cell_ = kWider * reach;
    const double nx = std::floor((x1 - x0_) / cell_) + 1, ny = std::floor((y1 - y0_) / cell_) + 1;
    if (!(nx * ny <= kMaxCells)) return;
    nx_ = int(nx), ny_ = int(ny);
    words_ = (points_.size() + 63) / 64;
    bits_.assign(std::size_t(nx_ * ny_) * words_, 0);
    for (std::size_t i = 0; i < points_.size(); ++i) {
        const int ix = std::min(int((points_[i][0] - x0_) / cell_), nx_ - 1);
        const int iy = std::min(int((points_[i][1] - y0_) / cell_), ny_ - 1);
        bits_[cell(ix, iy) * words_ + i / 64] |= std::uint64_t(1) << (i % 64);
    }
}

}  // namespace mobb::crowd
