#include "mobb/core/clearance.h"

#include <cmath>
#include <limits>

namespace mobb {

std::vector<ClearanceSample> clearance(const Path& a, const Placement& pa, const Path& b, const Placement& pb) {
    const Rigid2 ta = Rigid2::of(pa), tb = Rigid2::of(pb);
    std::vector<ClearanceSample> out;
    for (std::int64_t i = 0; i < std::int64_t(a.size()); ++i) {
        const double s0 = sample_time(pa, a.dt, i), s1 = sample_time(pa, a.dt, i + 1);
        const Sample& p = a.samples[std::size_t(i)];
        ClearanceSample best{s0, std::numeric_limits<double>::infinity(), i, -1};
        const SampleRange w = aligned_samples(s0, s1, pb, b.dt, std::int64_t(b.size()));
        for (std::int64_t k = w.k0; k <= w.k1; ++k) {
            if (!times_overlap(s0, s1, sample_time(pb, b.dt, k), sample_time(pb, b.dt, k + 1))) continue;
            const double gap = samples_gap(ta, p, tb, b.samples[std::size_t(k)]);
            if (gap < best.gap) best.gap = gap, best.j = k;
        }
        if (best.j >= 0) out.push_back(best);
    }
    return out;
}

}  // namespace mobb
