#include "policy/nav_field.h"
#include "mobb/core/assert.h"
#include "world/planar.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <queue>
#include <utility>

namespace mobb::crowd {

NavGrid::NavGrid(const World& world, double clear, double size)
    : x0(world.x0), y0(world.y0), cell(size), clearance(clear) {
    nx = std::max(1, int(std::ceil(world.width() / cell)));
    ny = std::max(1, int(std::ceil(world.height() / cell)));
    free.assign(std::size_t(nx) * std::size_t(ny), 1);
    // Each solid blocks the cells of its bounds grown by the clearance whose centre it comes near: the cells
    // a test over every cell would block, in time proportional to the solids' ground, not cells x solids.
    for (const Polygon& p : world.solids()) {
        const std::array<double, 4> b = bounds(p);
        const int ix0 = std::max(0, int(std::floor((b[0] - clearance - x0) / cell)));
        const int ix1 = std::min(nx - 1, int(std::floor((b[2] + clearance - x0) / cell)));
        const int iy0 = std::max(0, int(std::floor((b[1] - clearance - y0) / cell)));
        const int iy1 = std::min(ny - 1, int(std::floor((b[3] + clearance - y0) / cell)));
        for (int ix = ix0; ix <= ix1; ++ix)
            for (int iy = iy0; iy <= iy1; ++iy) {
                char& f = free[std::size_t(ix) * std::size_t(ny) + std::size_t(iy)];
                if (f && disk_overlaps(p, x0 + (ix + 0.5) * cell, y0 + (iy + 0.5) * cell, clearance)) f = 0;
            }
    }
}

double nav_cell(const World& world, std::size_t fields) {
    const double cells = kFieldBytes / (kBytesPerCell * double(std::max<std::size_t>(1, fields)));
    return std::max(kNavCell, std::sqrt(world.width() * world.height() / cells));
}

void NavGrid::block_disk(double x, double y, double r) {
    just_blocked.clear();
    const double reach = r + clearance;
    const int ix0 = std::max(0, int((x - reach - x0) / cell)), ix1 = std::min(nx - 1, int((x + reach - x0) / cell));
    const int iy0 = std::max(0, int((y - reach - y0) / cell)), iy1 = std::min(ny - 1, int((y + reach - y0) / cell));
    for (int ix = ix0; ix <= ix1; ++ix)
        for (int iy = iy0; iy <= iy1; ++iy) {
            const std::size_t c = std::size_t(ix) * std::size_t(ny) + std::size_t(iy);
            if (free[c] && std::hypot(x0 + (ix + 0.5) * cell - x, y0 + (iy + 0.5) * cell - y) < reach) {
                free[c] = 0;
                just_blocked.push_back(c);
            }
        }
}

NavField::NavField(const NavGrid& grid, std::array<double, 2> goal)
    : x0_(grid.x0), y0_(grid.y0), cell_(grid.cell), nx_(grid.nx), ny_(grid.ny), nxd_(nx_), nyd_(ny_), goal_(goal) {
    value_.assign(std::size_t(nx_) * std::size_t(ny_), kUnreachable);
    parent_.assign(value_.size(), -1);
    cut_.assign(value_.size(), 0);
    const int gx = std::clamp(int((goal[0] - x0_) / cell_), 0, nx_ - 1);
    const int gy = std::clamp(int((goal[1] - y0_) / cell_), 0, ny_ - 1);
    goal_cell_ = std::size_t(gx) * std::size_t(ny_) + std::size_t(gy);
    value_[goal_cell_] = 0;
    Heap open;
    open.push({0.0, goal_cell_});
    spread(grid, open, nullptr);
}

// Dijkstra from what `open` holds into the free cells (into the `only` ones, when given).
void NavField::spread(const NavGrid& grid, Heap& open, const std::vector<char>* only) {
    while (!open.empty()) {
        const double d = open.top().first;  // not a structured binding: C++17 lambdas cannot capture one
        const std::size_t c = open.top().second;
        open.pop();
        if (d > value_[c]) continue;
        grid.for_neighbours(c, [&](std::size_t n, double step) {
            if (!grid.free[n] || (only && !(*only)[n]) || !(d + step < value_[n])) return;
            value_[n] = d + step;
            parent_[n] = int(c);
            open.push({value_[n], n});
        });
    }
}

// The cells whose shortest path ran through a cell just blocked: those cells and their descendants
// along parent_ (a cell's children are among its neighbours), into cuts_ (marked in cut_).
void NavField::cut_paths(const NavGrid& grid) {
    cuts_.clear();
    for (std::size_t k : grid.just_blocked)
        if (k != goal_cell_ && value_[k] < kUnreachable) cut_[k] = 1, cuts_.push_back(k);
    for (std::size_t i = 0; i < cuts_.size(); ++i) {
        const std::size_t c = cuts_[i];
        grid.for_neighbours(c, [&](std::size_t n, double) {
            if (!cut_[n] && parent_[n] == int(c)) cut_[n] = 1, cuts_.push_back(n);
        });
    }
}

// Blocking cells only lengthens paths: the cut cells are solved again from the cells around them, whose
// values still hold; the rest keep theirs.
void NavField::block(const NavGrid& grid) {
    cut_paths(grid);
    if (cuts_.empty()) return;
    for (std::size_t k : cuts_) value_[k] = kUnreachable, parent_[k] = -1;
    Heap open;
    for (std::size_t k : cuts_) {
        if (!grid.free[k]) continue;
        grid.for_neighbours(k, [&](std::size_t n, double step) {
            if (cut_[n] || !grid.free[n] || value_[n] >= kUnreachable) return;
            if (value_[n] + step < value_[k]) value_[k] = value_[n] + step, parent_[k] = int(n);
        });
        if (value_[k] < kUnreachable) open.push({value_[k], k});
    }
    spread(grid, open, &cut_);
    for (std::size_t k : cuts_) cut_[k] = 0;
    MOBB_ASSERT(value_[goal_cell_] == 0);  // the goal is never cut
}

double NavField::downhill(double x, double y) const {
    const double h = 0.5 * cell_;
    const double e = distance(x + h, y), w = distance(x - h, y), n = distance(x, y + h), s = distance(x, y - h);
    if (std::max({e, w, n, s}) < kUnreachable && (e != w || n != s)) return std::atan2(s - n, w - e);
    return std::atan2(goal_[1] - y, goal_[0] - x);
}

}  // namespace mobb::crowd
