#include "collision/batch_grid.h"

#include <algorithm>
#include <stdexcept>

#include "mobb/core/assert.h"
#include "mobb/util/worker_pool.h"

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
    occupied_.resize((cells_.size() + 63) / 64);
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
            if (cells_[c].empty()) used_.push_back(c), occupied_[c >> 6] |= std::uint64_t(1) << (c & 63);
            cells_[c].push_back(e);
        }
}

// Three steps: the groups laid out in index order (one thread: a prefix sum), their boxes and unions (by
// group), and the cells (by bands of columns: each band visits every group, in order, so a cell's list is
// in index order as add() leaves it).
void BatchGrid::fill(std::size_t n, const std::function<Span(std::size_t)>& boxes, util::WorkerPool& pool) {
    MOBB_ASSERT(groups_.empty() && used_.empty());
    std::size_t total = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const auto [first, last] = boxes(i);
        if (first == last) continue;
        groups_.push_back({int(i), *first, total, total + std::size_t(last - first)});
        total += std::size_t(last - first);
    }
    boxes_.resize(total);
    pool.for_each(
        groups_.size(),
        [&](std::size_t e, int) {
            Group& g = groups_[e];
            const auto [first, last] = boxes(std::size_t(g.index));
            std::copy(first, last, boxes_.begin() + std::ptrdiff_t(g.begin));
            for (const SpaceTimeBox* b = first; b != last; ++b) g.all.enclose(*b);
        },
        64);
    const int bands = pool.size() > 1 ? std::min(nx_, 4 * pool.size()) : 1;
    band_used_.resize(std::size_t(bands));
    pool.for_each(std::size_t(bands), [&](std::size_t band, int) {
        const int lo = int(std::int64_t(nx_) * std::int64_t(band) / bands);
        const int hi = int(std::int64_t(nx_) * std::int64_t(band + 1) / bands);
        std::vector<std::size_t>& used = band_used_[band];
        used.clear();
        for (std::size_t e = 0; e < groups_.size(); ++e) {
            const SpaceTimeBox& box = groups_[e].all;
            const int ix0 = std::max(lo, column(box.x0, x0_, nx_)), ix1 = std::min(hi - 1, column(box.x1, x0_, nx_));
            if (ix0 > ix1) continue;
            const int iy0 = column(box.y0, y0_, ny_), iy1 = column(box.y1, y0_, ny_);
            for (int ix = ix0; ix <= ix1; ++ix)
                for (int iy = iy0; iy <= iy1; ++iy) {
                    const std::size_t c = std::size_t(ix) * std::size_t(ny_) + std::size_t(iy);
                    if (cells_[c].empty()) used.push_back(c);
                    cells_[c].push_back(int(e));
                }
        }
    });
    for (const std::vector<std::size_t>& used : band_used_) used_.insert(used_.end(), used.begin(), used.end());
    for (std::size_t c : used_) occupied_[c >> 6] |= std::uint64_t(1) << (c & 63);  // a word spans bands
}

bool BatchGrid::any_between(const SpaceTimeBox& box, int from, int below) const {
    const int ix0 = column(box.x0, x0_, nx_), ix1 = column(box.x1, x0_, nx_);
    const int iy0 = column(box.y0, y0_, ny_), iy1 = column(box.y1, y0_, ny_);
    for (int ix = ix0; ix <= ix1; ++ix)
        for (int iy = iy0; iy <= iy1; ++iy) {
            const std::size_t c = std::size_t(ix) * std::size_t(ny_) + std::size_t(iy);
            if (!occupied(c)) continue;
            for (int e : cells_[c]) {
                const Group& g = groups_[std::size_t(e)];
                if (g.index >= below) break;  // indices were added in increasing order
                if (g.index >= from && overlaps(g, box)) return true;
            }
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
            const std::size_t c = std::size_t(ix) * std::size_t(ny_) + std::size_t(iy);
            if (!occupied(c)) continue;
            const std::vector<int>& cell = cells_[c];
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

void BatchGrid::clear() {
    for (std::size_t c : used_) cells_[c].clear(), occupied_[c >> 6] = 0;
    used_.clear();
    groups_.clear();
    boxes_.clear();
}

}  // namespace mobb::crowd
