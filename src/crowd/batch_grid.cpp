#include "batch_grid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mobb::crowd {

// Any cell size finds every overlap; a huge world only gets coarser cells.
BatchGrid::BatchGrid(double cell, double width, double height) {
    if (!(cell > 0)) throw std::invalid_argument("batch grid: cell size must be positive");
    width = std::max(0.0, width), height = std::max(0.0, height);
    cell_ = std::max({cell, width / 512, height / 512});
    nx_ = int(width / cell_) + 1;
    ny_ = int(height / cell_) + 1;
    cells_.resize(std::size_t(nx_) * std::size_t(ny_));
}

int BatchGrid::column(double v, int n) const {
    const double c = std::floor(v / cell_);
    return c < 0 ? 0 : c >= double(n - 1) ? n - 1 : int(c);
}

void BatchGrid::add(int index, const SpaceTimeBox& box) {
    if (std::size_t(index) >= boxes_.size()) boxes_.resize(std::size_t(index) + 1);
    boxes_[std::size_t(index)] = box;
    for (int ix = column(box.x0, nx_); ix <= column(box.x1, nx_); ++ix)
        for (int iy = column(box.y0, ny_); iy <= column(box.y1, ny_); ++iy) {
            const std::size_t c = std::size_t(ix) * std::size_t(ny_) + std::size_t(iy);
            if (cells_[c].empty()) used_.push_back(c);
            cells_[c].push_back(index);
        }
}

bool BatchGrid::any_before(const SpaceTimeBox& box, int below) const {
    for (int ix = column(box.x0, nx_); ix <= column(box.x1, nx_); ++ix)
        for (int iy = column(box.y0, ny_); iy <= column(box.y1, ny_); ++iy)
            for (int j : cells_[std::size_t(ix) * std::size_t(ny_) + std::size_t(iy)]) {
                if (j >= below) break;  // indices were added in increasing order
                if (boxes_[std::size_t(j)].overlaps(box)) return true;
            }
    return false;
}

void BatchGrid::clear() {
    for (std::size_t c : used_) cells_[c].clear();
    used_.clear();
}

}  // namespace mobb::crowd
