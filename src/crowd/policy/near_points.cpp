#include "policy/near_points.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace mobb::crowd {

namespace {
// Cells a hundredth wider than reach / kSplit: two points within reach lie at most kSplit cells apart along
// each axis, the rounding of their cell coordinates (about 1e-14 of a cell) notwithstanding.
constexpr double kWider = 1.01;
constexpr int kMaxCells = 4096;  // cells as wide as reach; beyond (points spread far, or a reach near 0): no grid
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
    cell_ = kWider * reach / kSplit;
    const double nx = std::floor((x1 - x0_) / cell_) + 1, ny = std::floor((y1 - y0_) / cell_) + 1;
    if (!(nx * ny <= double(kMaxCells) * kSplit * kSplit)) return;
    // Each point's bit in the block of every cell within kSplit of its own, the points' grid kSplit cells in
    // from the block grid's edges.
    const int bx = int(nx) + 2 * kSplit, by = int(ny) + 2 * kSplit;
    const std::size_t words = (points_.size() + 63) / 64;
    blocks_.assign(std::size_t(bx) * std::size_t(by) * words, 0);
    for (std::size_t i = 0; i < points_.size(); ++i) {
        const int ix = std::min(int((points_[i][0] - x0_) / cell_), int(nx) - 1);
        const int iy = std::min(int((points_[i][1] - y0_) / cell_), int(ny) - 1);
        const std::uint64_t bit = std::uint64_t(1) << (i % 64);
        for (int jx = ix; jx <= ix + 2 * kSplit; ++jx) {
            std::uint64_t* column = &blocks_[std::size_t(jx) * std::size_t(by) * words + i / 64];
            for (int jy = iy; jy <= iy + 2 * kSplit; ++jy) column[std::size_t(jy) * words] |= bit;
        }
    }
    bx_ = bx, by_ = by, words_ = words;
}

}  // namespace mobb::crowd
