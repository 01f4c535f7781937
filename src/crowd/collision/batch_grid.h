// The boxes chosen by the choice points of one frame, so each choice point can tell whether a plan
// committed before it in the same frame (lower agent id), and after the commits its evaluation saw, may
// change that evaluation (paper section 5's choice points, run in parallel: see Simulation in crowd.cpp).
#pragma once
#include <cstddef>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

#include "mobb/crowd/collision/broad_phase.h"

namespace mobb::util {
class WorkerPool;
}

namespace mobb::crowd {

/// A flat grid over the world [x0, x1] x [y0, y1]; boxes beyond it land in the border cells (clamping
/// keeps every overlap findable), so no hashing. Filled sequentially, then read by any number of threads.
/// A choice point's boxes enter as one group under their union: one entry per cell for all of them (a
/// plan's boxes lie close together), its boxes tested only where the union overlaps.
class BatchGrid {
public:
    BatchGrid(double cell, double x0, double y0, double x1, double y1);

    /// Adds the boxes [first, last) of the batch's choice point `index`; indices are added in increasing order.
    void add(int index, const SpaceTimeBox* first, const SpaceTimeBox* last);
    void add(int index, const std::vector<SpaceTimeBox>& boxes) {
        add(index, boxes.data(), boxes.data() + boxes.size());
    }
    /// The boxes of indices 0 .. n - 1 into an empty grid at once, by `pool`'s workers: the same as add()
    /// of each in turn. boxes(i) gives index i's [first, last).
    using Span = std::pair<const SpaceTimeBox*, const SpaceTimeBox*>;
    void fill(std::size_t n, const std::function<Span(std::size_t)>& boxes, util::WorkerPool& pool);
    /// Whether a box added with an index in [from, below) overlaps `box`.
    bool any_between(const SpaceTimeBox& box, int from, int below) const;
    /// The largest index in [from, below) whose boxes overlap `box`; -1 when none does.
    int last_between(const SpaceTimeBox& box, int from, int below) const;
    /// The largest index added; -1 when empty.
    int last_index() const { return groups_.empty() ? -1 : groups_.back().index; }
    /// Empties the grid (only the cells used are visited).
    void clear();

private:
    struct Group {
        int index;
        SpaceTimeBox all;        // the union of its boxes
        std::size_t begin, end;  // its boxes in boxes_
    };
    bool overlaps(const Group& g, const SpaceTimeBox& box) const;  // one of its boxes overlaps `box`
    // Clamped first, so no floor() is needed (a library call): truncation is floor from 0 on. Multiplying
    // by the inverse may put a box one cell over, but add() and any_before() alike. Inline: a call
    // costs as much as the rest.
    int column(double v, double origin, int n) const {
        const double c = (v - origin) * inv_cell_;
        return c < 0 ? 0 : c >= double(n - 1) ? n - 1 : int(c);
    }

    double cell_ = 1, inv_cell_ = 1, x0_ = 0, y0_ = 0;
    int nx_ = 1, ny_ = 1;
    std::vector<std::vector<int>> cells_;  // groups, in order of addition
    // One bit per cell, set when it holds a group: most cells are empty, and the bits stay in the cache
    // where the cells' arrays do not.
    std::vector<std::uint64_t> occupied_;
    bool occupied(std::size_t c) const { return (occupied_[c >> 6] >> (c & 63)) & 1; }
    std::vector<std::size_t> used_;  // cells holding something
    std::vector<Group> groups_;
    std::vector<SpaceTimeBox> boxes_;
    std::vector<std::vector<std::size_t>> band_used_;  // scratch of fill(): per band, the cells it began
};

}  // namespace mobb::crowd
