// The clips chosen by the choice points of one frame, so each choice point can tell whether a clip
// chosen before it in the same frame (lower agent id) may change its evaluation (paper section 5's
// choice points, run in parallel: see Simulation in crowd.cpp).
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "mobb/crowd/broad_phase.h"

namespace mobb::crowd {

/// A flat grid over the world [0, W] x [0, H]; boxes beyond it land in the border cells (clamping
/// keeps every overlap findable), so no hashing. Filled sequentially, then read by any number of threads.
class BatchGrid {
public:
    BatchGrid(double cell, double width, double height);

    /// Adds the box of the batch's choice point `index`; indices are added in increasing order.
    void add(int index, const SpaceTimeBox& box);
    /// Whether a box added with an index below `below` overlaps `box`.
    bool any_before(const SpaceTimeBox& box, int below) const;
    /// Empties the grid (only the cells used are visited).
    void clear();

private:
    int column(double v, int n) const;

    double cell_ = 1;
    int nx_ = 1, ny_ = 1;
    std::vector<std::vector<int>> cells_;
    std::vector<std::size_t> used_;    // cells holding something
    std::vector<SpaceTimeBox> boxes_;  // by index
};

}  // namespace mobb::crowd
