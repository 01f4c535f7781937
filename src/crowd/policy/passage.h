// Passages: the places of a world where the free ground is narrow between solids on both sides - a door,
// a gap between obstacles, a narrow corridor - and how far each point is from one. Letting through
// (CrowdTuning::let_through) reads it: at a passage, the agent farther from it keeps out of the way of
// one coming through it the other way.
#pragma once
#include <vector>

#include "mobb/crowd/world/world.h"
#include "policy/nav_field.h"

namespace mobb::crowd {

class PassageMap {
public:
    /// Marks as a passage every cell (of `cell` metres) of `world` with a chord of free ground - through its
    /// centre, along x, y or a diagonal, solid to solid - shorter than `narrow` metres beside which the
    /// ground opens up both ways (a chord as wide, within `narrow` metres across it: not a room's corner),
    /// and measures from each free cell the path over free cells to the nearest passage, up to `reach`
    /// metres. The world's edges are solid when it is walled; an open edge ends no chord.
    PassageMap(const World& world, double narrow, double reach, double cell);

    /// Metres from (x, y) to the nearest passage over free ground: 0 inside one, `reach` or more beyond
    /// `reach` (or outside the world, or in a solid).
    double distance(double x, double y) const;
    bool any() const { return any_; }
    /// Metres of free ground across the way `way` (radians) at (x, y): the chord through the cell holding
    /// the point along whichever of x, y and the diagonals lies nearest square to the way, `cap` at most
    /// (also at an open edge of the world); 0 outside the world or in a solid.
    double across(double x, double y, double way, double cap) const;

private:
    double chord(int ix, int iy, int dx, int dy, double cap) const;
    bool opens(int ix, int iy, int dx, int dy, double narrow) const;
    bool free_at(int ix, int iy) const;
    void spread(const std::vector<std::size_t>& passages);

    NavGrid grid_;  ///< free: the cell's centre lies in no solid (clearance 0)
    double x0_, y0_, cell_, reach_;
    int nx_, ny_;
    bool walled_;
    bool any_ = false;
    std::vector<float> distance_;  ///< [ix * ny + iy]: metres to the nearest passage, capped at reach_
};

}  // namespace mobb::crowd
