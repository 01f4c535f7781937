#include "policy/passage.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

#include "mobb/core/angle.h"
#include "policy/nav_field.h"

namespace mobb::crowd {

namespace {
constexpr double kDiagonal = 1.4142135623730951;  // sqrt(2)
constexpr int kAxes[4][2] = {{1, 0}, {0, 1}, {1, 1}, {1, -1}};
}  // namespace

PassageMap::PassageMap(const World& world, double narrow, double reach, double cell)
    : grid_(world, 0, cell),
      x0_(world.x0),
      y0_(world.y0),
      cell_(cell),
      reach_(reach),
      nx_(grid_.nx),
      ny_(grid_.ny),
      walled_(world.walls) {
    std::vector<std::size_t> passages;
    for (int ix = 0; ix < nx_; ++ix)
        for (int iy = 0; iy < ny_; ++iy) {
            if (!free_at(ix, iy)) continue;
            for (const auto& d : kAxes)
                if (chord(ix, iy, d[0], d[1], narrow) < narrow && opens(ix, iy, d[0], d[1], narrow)) {
                    passages.push_back(std::size_t(ix) * std::size_t(ny_) + std::size_t(iy));
                    break;
                }
        }
    any_ = !passages.empty();
    spread(passages);
}

bool PassageMap::free_at(int ix, int iy) const {
    return grid_.free[std::size_t(ix) * std::size_t(ny_) + std::size_t(iy)] != 0;
}

// The chord through cell (ix, iy) along (dx, dy): the free cells either way to the first solid, times the
// step; `cap` as soon as it reaches that, and at an open edge of the world.
double PassageMap::chord(int ix, int iy, int dx, int dy, double cap) const {
    const double step = (dx && dy ? kDiagonal : 1.0) * cell_;
    double length = step;
    for (int sign : {1, -1})
        for (int k = 1;; ++k) {
            const int jx = ix + sign * k * dx, jy = iy + sign * k * dy;
            if (jx < 0 || jy < 0 || jx >= nx_ || jy >= ny_) {
                if (!walled_) return cap;
                break;
            }
            if (!free_at(jx, jy)) break;
            length += step;
            if (length >= cap) return cap;
        }
    return length;
}

// Whether the ground either side of the narrow chord through (ix, iy) along (dx, dy) opens up: stepping
// across it, both ways, a chord as wide as `narrow` comes before a solid, within `narrow` metres. A
// door's or a gap's does; a room's corner, where the ground only narrows further, does not.
bool PassageMap::opens(int ix, int iy, int dx, int dy, double narrow) const {
    const int px = -dy, py = dx;
    const double step = (px && py ? kDiagonal : 1.0) * cell_;
    for (int sign : {1, -1}) {
        bool opened = false;
        for (int k = 1; !opened && k * step <= narrow; ++k) {
            const int jx = ix + sign * k * px, jy = iy + sign * k * py;
            if (jx < 0 || jy < 0 || jx >= nx_ || jy >= ny_) {
                opened = !walled_;
                break;
            }
            if (!free_at(jx, jy)) break;
            opened = chord(jx, jy, dx, dy, narrow) >= narrow;
        }
        if (!opened) return false;
    }
    return true;
}

// Dijkstra over the free cells from every passage at once, 8-connected, no farther than reach_.
void PassageMap::spread(const std::vector<std::size_t>& passages) {
    distance_.assign(grid_.free.size(), float(reach_));
    using Entry = std::pair<double, std::size_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
    for (std::size_t c : passages) distance_[c] = 0, open.emplace(0.0, c);
    while (!open.empty()) {
        const double d = open.top().first;  // not a structured binding: lambdas cannot capture one in C++17
        const std::size_t c = open.top().second;
        open.pop();
        if (d > double(distance_[c])) continue;
        grid_.for_neighbours(c, [&](std::size_t n, double step) {
            if (grid_.free[n] && d + step < double(distance_[n]))
                distance_[n] = float(d + step), open.emplace(d + step, n);
        });
    }
}

double PassageMap::distance(double x, double y) const {
    const double fx = (x - x0_) / cell_, fy = (y - y0_) / cell_;
    if (!(fx >= 0 && fy >= 0 && fx < nx_ && fy < ny_)) return reach_;
    return double(distance_[std::size_t(int(fx)) * std::size_t(ny_) + std::size_t(int(fy))]);
}

double PassageMap::across(double x, double y, double way, double cap) const {
    const double fx = (x - x0_) / cell_, fy = (y - y0_) / cell_;
    if (!(fx >= 0 && fy >= 0 && fx < nx_ && fy < ny_)) return 0;
    const int ix = int(fx), iy = int(fy);
    if (!free_at(ix, iy)) return 0;
    // The axes' angles (kAxes), compared with the square to the way modulo 180 degrees.
    static constexpr double kAxisAngle[4] = {0, kPi / 2, kPi / 4, -kPi / 4};
    int best = 0;
    double nearest = 1e300;
    for (int k = 0; k < 4; ++k) {
        const double off = std::abs(std::remainder(way + kPi / 2 - kAxisAngle[k], kPi));
        if (off < nearest) nearest = off, best = k;
    }
    return chord(ix, iy, kAxes[best][0], kAxes[best][1], cap);
}

}  // namespace mobb::crowd
