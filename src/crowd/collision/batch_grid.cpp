#include "collision/batch_grid.h"

#include <algorithm>
#include <stdexcept>

namespace mobb::crowd {

// Any cell size finds every overlap; a huge world only gets coarser cells.
BatchGrid::BatchGrid(double cell, double x0, double y0, double x1, double y1) : x0_(x0), y0_(y0) {
    if (!(cell > 0)) throw std::invalid_argument("batch grid: cell size must be positive");
    const double width = std::max(0.0, x1 - x0), height = std::max(0.0, y1 - y0);
    cell_ = std::max({cell, width / 512, height / 512});
    inv_cell_ = 1 / cell_;
    nx_ = int(width / cell_) + 1;
    ny_ = int(height / cell_) + 1;
    cells_.resize(std::size_t(nx_) * std::size_t(ny_));
}

void BatchGrid::add(int index, const SpaceTimeBox* first, const SpaceTimeBox* last) {
    if (first == last) return;
    SpaceTimeBox box = *first;
    for (const SpaceTimeBox* b = first; b != last; ++b) box.enclose(*b);
    const int e = int(groups_.size());
    groups_.push_back({index, box, boxes_.size(), boxes_.size() + std::size_t(last - first)});
    boxes_.insert(boxes_.end(), first, last);
    const int ix0 = column(box.x0, x0_, nx_), ix1 = column(box.x1, x0_, nx_);
    const int iy0 = column(box.y0, y0_, ny_), iy1 = column(box.y1, y0_, ny_);
    for (int ix = ix0; ix <= ix1; ++ix)
        for (int iy = iy0; iy <= iy1; ++iy) {
            const std::size_t c = std::size_t(ix) * std::size_t(ny_) + std::size_t(iy);
            if (cells_[c].empty()) used_.push_back(c);
            cells_[c].push_back(e);
        }
}

bool BatchGrid::any_between(const SpaceTimeBox& box, int from, int below) const {
    const int ix0 = column(box.x0, x0_, nx_), ix1 = column(box.x1, x0_, nx_);
    const int iy0 = column(box.y0, y0_, ny_), iy1 = column(box.y1, y0_, ny_);
    for (int ix = ix0; ix <= ix1; ++ix)
        for (int iy = iy0; iy <= iy1; ++iy)
            for (int e : cells_[std::size_t(ix) * std::size_t(ny_) + std::size_t(iy)]) {
                const Group& g = groups_[std::size_t(e)];
                if (g.index >= below) break;  // indices were added in increasing order
                if (g.index >= from && overlaps(g, box)) return true;
            }
    return false;
}

bool BatchGrid::overlaps(const Group& g, const SpaceTimeBox& box) const {
    if (!g.all.overlaps(box)) return false;
    for (std::size_t b = g.begin; b < g.end; ++b)
        if (boxes_[b].overlaps(box)) return true;
    return false;
}

int BatchGrid::last_between(const SpaceTimeBox& box, int from, int below) const {
    const int ix0 = column(box.x0, x0_, nx_), ix1 = column(box.x1, x0_, nx_);
    const int iy0 = column(box.y0, y0_, ny_), iy1 = column(box.y1, y0_, ny_);
    int last = -1;
    for (int ix = ix0; ix <= ix1; ++ix)
        for (int iy = iy0; iy <= iy1; ++iy) {
            const std::vector<int>& cell = cells_[std::size_t(ix) * std::size_t(ny_) + std::size_t(iy)];
            // Backwards: indices were added in increasing order, so the first overlap met is the cell's last.
            for (auto e = cell.rbegin(); e != cell.rend(); ++e) {
                const Group& g = groups_[std::size_t(*e)];
                if (g.index >= below) continue;
                if (g.index < std::max(from, last + 1)) break;
                if (overlaps(g, box)) {
                    last = g.index;
                    break;
                }
            }
        }
    return last;
}

void BatchGrid::release() {
    for (std::size_t c : used_) std::vector<int>().swap(cells_[c]);
    used_ = {};
    groups_ = {};
    boxes_ = {};
}

void BatchGrid::clear() {
    for (std::size_t c : used_) cells_[c].clear();
    used_.clear();
    groups_.clear();
    boxes_.clear();
}

}  // namespace mobb::crowd
