// Distance to a goal around the obstacles: a grid over the world whose cells hold the length of the
// shortest 8-connected path to the goal through cells clear of every solid (Dijkstra). The goal
// policy ranks candidate clips by it.
#pragma once
#include <array>
#include <cstddef>
#include <functional>
#include <queue>
#include <utility>
#include <vector>

#include "mobb/crowd/world/world.h"
#include "world/planar.h"

namespace mobb::crowd {

/// Metres: the navigation grid's cell where memory allows (nav_cell).
inline constexpr double kNavCell = 0.25;
/// Bytes all of a policy's fields may take (one per goal): 1 GiB, so that a scenario of thousands of goals
/// over a large world coarsens its fields rather than run out of memory (4,000 goals over 200 x 200 m at
/// kNavCell would take 33 GB).
inline constexpr double kFieldBytes = double(std::size_t(1) << 30);
/// Bytes a field holds per cell: its value, its parent and its scratch mark.
inline constexpr double kBytesPerCell = sizeof(double) + sizeof(int) + sizeof(char);

/// The cell (metres) of a grid over `world` that `fields` fields fit in kFieldBytes: kNavCell, or coarser.
double nav_cell(const World& world, std::size_t fields);

/// Which cells of the world an agent's centre may cross: those whose centre is `clearance` metres clear
/// of every solid (World::solids()) and of the disks blocked since.
class NavGrid {
public:
    NavGrid(const World& world, double clear, double size = kNavCell);  ///< clearance = clear, cell = size (metres)

    /// Blocks the cells whose centre lies within r + clearance of (x, y): an agent standing there for good.
    void block_disk(double x, double y, double r);

    /// Whether the cell holding (x, y) is blocked (not free), or the point lies outside the grid.
    bool blocked(double x, double y) const {
        const double fx = (x - x0) / cell, fy = (y - y0) / cell;
        if (!(fx >= 0 && fy >= 0 && fx < nx && fy < ny)) return true;
        return !free[std::size_t(fx) * std::size_t(ny) + std::size_t(fy)];
    }

    double x0 = 0, y0 = 0, cell = 0.25, clearance = 0;
    int nx = 1, ny = 1;
    std::vector<char> free;                 ///< [ix * ny + iy]
    std::vector<std::size_t> just_blocked;  ///< the cells the last block_disk() blocked (free before it)

    /// Calls f(n, step) for each of cell c's eight neighbours n inside the grid, step the distance
    /// between their centres (metres).
    template <class F>
    void for_neighbours(std::size_t c, F&& f) const {
        const int ix = int(c / std::size_t(ny)), iy = int(c % std::size_t(ny));
        for (int dx = -1; dx <= 1; ++dx)
            for (int dy = -1; dy <= 1; ++dy) {
                const int jx = ix + dx, jy = iy + dy;
                if ((dx == 0 && dy == 0) || jx < 0 || jy < 0 || jx >= nx || jy >= ny) continue;
                f(std::size_t(jx) * std::size_t(ny) + std::size_t(jy), (dx && dy ? kDiagonal : 1.0) * cell);
            }
    }

private:
    static constexpr double kDiagonal = 1.4142135623730951;  // sqrt(2)
};

class NavField {
public:
    NavField(const NavGrid& grid, std::array<double, 2> goal);

    /// Path length (metres) from (x, y) to the goal: the value of the cell holding the point, plus the
    /// straight distance to that cell's centre; kUnreachable for blocked or cut-off cells and outside.
    /// Inline: the look-ahead reads it for every clip it pushes, and five times for each it scores.
    double distance(double x, double y) const {
        const double fx = (x - x0_) / cell_, fy = (y - y0_) / cell_;
        if (!(fx >= 0 && fy >= 0 && fx < nxd_ && fy < nyd_)) return kUnreachable;
        const int ix = int(fx), iy = int(fy);
        const double v = value_[std::size_t(ix) * std::size_t(ny_) + std::size_t(iy)];
        if (v >= kUnreachable) return kUnreachable;
        const double dx = fx - (ix + 0.5), dy = fy - (iy + 0.5);
        return v + planar_distance(dx, dy) * cell_;
    }

    /// The direction (radians) in which distance() falls fastest at (x, y), from central differences half a
    /// cell apart; the straight direction to the goal where the field has no slope to read.
    double downhill(double x, double y) const;

    static constexpr double kUnreachable = 1e9;

    /// Brings the field up to date after block_disk() blocked the cells `grid.just_blocked` of `grid` (the
    /// grid it was built on): the same distances as building it again, computed only where a path ran
    /// through a blocked cell - in time proportional to those cells, not to the grid.
    void block(const NavGrid& grid);

private:
    using Heap = std::priority_queue<std::pair<double, std::size_t>, std::vector<std::pair<double, std::size_t>>,
                                     std::greater<>>;
    void spread(const NavGrid& grid, Heap& open, const std::vector<char>* only);
    void cut_paths(const NavGrid& grid);

    double x0_, y0_, cell_;
    int nx_, ny_;
    double nxd_, nyd_;  // nx_, ny_ (compared with doubles)
    std::array<double, 2> goal_;
    std::vector<double> value_;
    std::vector<int> parent_;        ///< the neighbour each cell's shortest path goes on through (-1: none)
    std::vector<char> cut_;          ///< scratch of block(): per cell, whether its path met a blocked cell
    std::vector<std::size_t> cuts_;  ///< scratch of block(): those cells
    std::size_t goal_cell_ = 0;
};

}  // namespace mobb::crowd
