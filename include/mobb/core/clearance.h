// Clearance over time between two placed clips: how far apart their characters are at each moment
// beyond the sum of their radii - the margin of the paper's Equation 1 (section 3), negative exactly
// where the two cylinders overlap. The viewer plots it under the query; the query itself never needs it.
#pragma once
#include <cstdint>
#include <vector>

#include "mobb/core/path.h"

namespace mobb {

struct ClearanceSample {
    double t = 0;    ///< global start time of sample i of a (seconds)
    double gap = 0;  ///< |p_a,i - p_b,j| - (r_a,i + r_b,j), metres: below 0 the disks overlap
    std::int64_t i = 0, j = 0;
};

/// One entry per sample i of a that overlaps some sample of b in time (times_overlap), in time order:
/// the smallest gap over those samples j of b, and the j attaining it. Empty when the clips never
/// overlap in time. Some gap is negative exactly when collide_brute(a, pa, b, pb) is true.
std::vector<ClearanceSample> clearance(const Path& a, const Placement& pa, const Path& b, const Placement& pb);

/// Clearance of every sample of every clip to its nearest other clip: entry [c][i] is the smallest
/// gap (as in clearance()) between sample i of clip c and the samples of any other clip overlapping it
/// in time, metres; +infinity where no other clip overlaps it in time. paths and places have one entry
/// per clip. Every pair of clips is visited once (both clips' entries updated), pairs whose time
/// ranges are disjoint skipped: O(clips^2 + pairs overlapping in time x samples).
std::vector<std::vector<double>> nearest_clearance(const std::vector<const Path*>& paths,
                                                   const std::vector<Placement>& places);

}  // namespace mobb
