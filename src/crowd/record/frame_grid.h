// A grid over the agents of one frame, for the frame-by-frame contact check: frame_contacts (record.cpp)
// on a whole record and FrameStream (frame_stream.cpp) on a run's frames as they complete. Private to
// src/crowd.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace mobb::crowd {

// The agents of one frame sorted into a flat grid over their bounding rectangle (a counting sort, so
// linear in the agents), their disks stored in cell order so that scans read contiguous memory. Cells
// are wider than any contact distance, so contacts are between agents of neighbouring cells, and there
// are at most about 2 n cells however far agents stray.
class FrameGrid {
public:
    struct Disk {
        double x, y, r;
        int agent;
    };

    /// Sorts the n disks of one frame (the agents in the run then).
    void build(const Disk* frame, std::size_t n, double reach) {
        x0_ = y0_ = 1e300;
        double x1 = -1e300, y1 = -1e300;
        for (std::size_t a = 0; a < n; ++a)
            x0_ = std::min(x0_, frame[a].x), y0_ = std::min(y0_, frame[a].y), x1 = std::max(x1, frame[a].x),
            y1 = std::max(y1, frame[a].y);
        const double w = x1 - x0_, h = y1 - y0_, count = double(n);
        // The margin keeps rounding of (x - x0) / cell from putting two agents closer than `reach` two
        // cells apart.
        cell_ = std::max({reach * (1 + 1e-9), std::sqrt(w * h / count), (w + h) / count, 1e-6});
        nx_ = int(w / cell_) + 1, ny_ = int(h / cell_) + 1;
        cell_of_.resize(n);
        first_.assign(std::size_t(nx_) * std::size_t(ny_) + 1, 0);
        for (std::size_t a = 0; a < n; ++a) {
            cell_of_[a] = cell(column(frame[a].x - x0_, nx_), column(frame[a].y - y0_, ny_));
            ++first_[cell_of_[a] + 1];
        }
        for (std::size_t c = 1; c < first_.size(); ++c) first_[c] += first_[c - 1];
        disks_.resize(n);
        fill_.assign(first_.begin(), first_.end() - 1);
        for (std::size_t a = 0; a < n; ++a) disks_[fill_[cell_of_[a]]++] = frame[a];
    }

    /// Calls f(a, b) once for every unordered pair of agents whose disks overlap (|p_a - p_b| < r_a + r_b).
    template <class F>
    void overlaps(F&& f) const {
        overlaps(0, nx_, f);
    }

    int columns() const { return nx_; }

    /// overlaps() for the pairs whose first disk lies in columns [from, to): disjoint ranges of columns
    /// share the pairs out without repeating one.
    template <class F>
    void overlaps(int from, int to, F&& f) const {
        for (int ix = from; ix < to; ++ix)
            for (int iy = 0; iy < ny_; ++iy) {
                const std::size_t c = cell(ix, iy);
                for (std::size_t i = first_[c]; i < first_[c + 1]; ++i) {
                    test(i, i + 1, first_[c + 1], f);                            // the rest of its cell
                    if (iy + 1 < ny_) test(i, first_[c + 1], first_[c + 2], f);  // the cell above
                    if (ix + 1 < nx_) {                                          // the three cells to the right
                        const std::size_t lo = cell(ix + 1, std::max(0, iy - 1)),
                                          hi = cell(ix + 1, std::min(ny_ - 1, iy + 1));
                        test(i, first_[lo], first_[hi + 1], f);
                    }
                }
            }
    }

private:
    int column(double d, int n) const { return std::clamp(int(d / cell_), 0, n - 1); }
    std::size_t cell(int ix, int iy) const { return std::size_t(ix) * std::size_t(ny_) + std::size_t(iy); }

    template <class F>
    void test(std::size_t i, std::size_t lo, std::size_t hi, F& f) const {
        const Disk& a = disks_[i];
        for (std::size_t j = lo; j < hi; ++j) {
            const Disk& b = disks_[j];
            const double dx = a.x - b.x, dy = a.y - b.y, r = a.r + b.r;
            if (dx * dx + dy * dy < r * r) f(a.agent, b.agent);
        }
    }

    double x0_ = 0, y0_ = 0, cell_ = 1;
    int nx_ = 1, ny_ = 1;
    std::vector<std::size_t> cell_of_, first_, fill_;
    std::vector<Disk> disks_;
};

}  // namespace mobb::crowd
