#include "nav_field.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <queue>
#include <utility>

namespace mobb::crowd {

NavGrid::NavGrid(const World& world, double clear, double size)
    : x0(world.x0), y0(world.y0), cell(size), clearance(clear) {
    nx = std::max(1, int(std::ceil(world.width() / cell)));
    ny = std::max(1, int(std::ceil(world.height() / cell)));
    free.assign(std::size_t(nx) * std::size_t(ny), 1);
    const std::vector<Polygon> solids = world.solids();
    for (int ix = 0; ix < nx; ++ix)
        for (int iy = 0; iy < ny; ++iy) {
            const double x = x0 + (ix + 0.5) * cell, y = y0 + (iy + 0.5) * cell;
            for (const Polygon& p : solids)
                if (disk_overlaps(p, x, y, clearance)) {
                    free[std::size_t(ix) * std::size_t(ny) + std::size_t(iy)] = 0;
                    break;
                }
        }
}

void NavGrid::block_disk(double x, double y, double r) {
    const double reach = r + clearance;
    const int ix0 = std::max(0, int((x - reach - x0) / cell)), ix1 = std::min(nx - 1, int((x + reach - x0) / cell));
    const int iy0 = std::max(0, int((y - reach - y0) / cell)), iy1 = std::min(ny - 1, int((y + reach - y0) / cell));
    for (int ix = ix0; ix <= ix1; ++ix)
        for (int iy = iy0; iy <= iy1; ++iy)
            if (std::hypot(x0 + (ix + 0.5) * cell - x, y0 + (iy + 0.5) * cell - y) < reach)
                free[std::size_t(ix) * std::size_t(ny) + std::size_t(iy)] = 0;
}

namespace {

using Item = std::pair<double, std::size_t>;
using Heap = std::priority_queue<Item, std::vector<Item>, std::greater<>>;

}  // namespace

NavField::NavField(const NavGrid& grid, std::array<double, 2> goal)
    : x0_(grid.x0), y0_(grid.y0), cell_(grid.cell), nx_(grid.nx), ny_(grid.ny), goal_(goal) {
    value_.assign(std::size_t(nx_) * std::size_t(ny_), kUnreachable);
    parent_.assign(value_.size(), -1);
    const int gx = std::clamp(int((goal[0] - x0_) / cell_), 0, nx_ - 1);
    const int gy = std::clamp(int((goal[1] - y0_) / cell_), 0, ny_ - 1);
    goal_cell_ = std::size_t(gx) * std::size_t(ny_) + std::size_t(gy);
    value_[goal_cell_] = 0;
    Heap open;
    open.push({0.0, goal_cell_});
    spread(grid, open, nullptr, order_);
}

// Dijkstra from what `open` holds into the free cells (into the `only` ones, when given), appending
// the cells in the order they settle (by value): the order block() reads parents before children in.
void NavField::spread(const NavGrid& grid, Heap& open, const std::vector<char>* only, std::vector<int>& settled) {
    while (!open.empty()) {
        const auto [d, c] = open.top();
        open.pop();
        if (d > value_[c]) continue;
        settled.push_back(int(c));
        const int ix = int(c / std::size_t(ny_)), iy = int(c % std::size_t(ny_));
        for (int dx = -1; dx <= 1; ++dx)
            for (int dy = -1; dy <= 1; ++dy) {
                const int jx = ix + dx, jy = iy + dy;
                if ((dx == 0 && dy == 0) || jx < 0 || jy < 0 || jx >= nx_ || jy >= ny_) continue;
                const std::size_t n = std::size_t(jx) * std::size_t(ny_) + std::size_t(jy);
                if (!grid.free[n] || (only && !(*only)[n])) continue;
                const double step = (dx && dy ? std::sqrt(2.0) : 1.0) * cell_;
                if (d + step < value_[n]) {
                    value_[n] = d + step;
                    parent_[n] = int(c);
                    open.push({value_[n], n});
                }
            }
    }
}

// Blocking cells only lengthens paths: the cells whose shortest path ran through a newly blocked one
// (its descendants along parent_, found in one pass in settling order) are solved again from the
// cells around them, whose values still hold; the rest keep theirs.
void NavField::block(const NavGrid& grid) {
    std::vector<char> affected(value_.size(), 0);
    std::size_t count = 0;
    for (int c : order_) {
        const auto k = std::size_t(c);
        affected[k] = (k != goal_cell_ && !grid.free[k]) || (parent_[k] >= 0 && affected[std::size_t(parent_[k])]);
        count += affected[k];
    }
    if (count == 0) return;
    std::vector<int> kept, redone;
    kept.reserve(order_.size());
    for (int c : order_)
        if (!affected[std::size_t(c)]) kept.push_back(c);
    Heap open;
    for (int c : order_) {
        const auto k = std::size_t(c);
        if (!affected[k]) continue;
        value_[k] = kUnreachable;
        parent_[k] = -1;
    }
    for (int c : order_) {
        const auto k = std::size_t(c);
        if (!affected[k] || !grid.free[k]) continue;
        const int ix = int(k / std::size_t(ny_)), iy = int(k % std::size_t(ny_));
        for (int dx = -1; dx <= 1; ++dx)
            for (int dy = -1; dy <= 1; ++dy) {
                const int jx = ix + dx, jy = iy + dy;
                if ((dx == 0 && dy == 0) || jx < 0 || jy < 0 || jx >= nx_ || jy >= ny_) continue;
                const std::size_t n = std::size_t(jx) * std::size_t(ny_) + std::size_t(jy);
                if (affected[n] || value_[n] >= kUnreachable) continue;
                const double v = value_[n] + (dx && dy ? std::sqrt(2.0) : 1.0) * cell_;
                if (v < value_[k]) value_[k] = v, parent_[k] = int(n);
            }
        if (value_[k] < kUnreachable) open.push({value_[k], k});
    }
    spread(grid, open, &affected, redone);
    order_.clear();
    std::merge(kept.begin(), kept.end(), redone.begin(), redone.end(), std::back_inserter(order_),
               [&](int a, int b) { return value_[std::size_t(a)] < value_[std::size_t(b)]; });
}

double NavField::downhill(double x, double y) const {
    const double h = 0.5 * cell_;
    const double e = distance(x + h, y), w = distance(x - h, y), n = distance(x, y + h), s = distance(x, y - h);
    if (std::max({e, w, n, s}) < kUnreachable && (e != w || n != s)) return std::atan2(s - n, w - e);
    return std::atan2(goal_[1] - y, goal_[0] - x);
}

double NavField::distance(double x, double y) const {
    const double fx = (x - x0_) / cell_, fy = (y - y0_) / cell_;
    if (fx < 0 || fy < 0 || fx >= nx_ || fy >= ny_) return kUnreachable;
    const int ix = int(fx), iy = int(fy);
    const double v = value_[std::size_t(ix) * std::size_t(ny_) + std::size_t(iy)];
    if (v >= kUnreachable) return kUnreachable;
    return v + std::hypot(fx - (ix + 0.5), fy - (iy + 0.5)) * cell_;
}

}  // namespace mobb::crowd
