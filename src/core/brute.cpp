#include "mobb/core/brute.h"

#include <algorithm>
#include <cmath>

namespace mobb {

bool collide_brute(const Path& a, const Placement& pa, const Path& b, const Placement& pb, QueryStats* stats,
                   SamplePair* hit) {
    const Rigid2 ta = Rigid2::of(pa), tb = Rigid2::of(pb);
    const std::int64_t n = std::int64_t(a.size()), m = std::int64_t(b.size());
    std::uint64_t tested = 0;
    bool found = false;
    for (std::int64_t i = 0; i < n && !found; ++i) {
        const double s0 = sample_time(pa, a.dt, i), s1 = sample_time(pa, a.dt, i + 1);
        const SampleRange w = aligned_samples(s0, s1, pb, b.dt, m);
        for (std::int64_t k = w.k0; k <= w.k1; ++k) {
            if (!times_overlap(s0, s1, sample_time(pb, b.dt, k), sample_time(pb, b.dt, k + 1))) continue;
            ++tested;
            if (samples_overlap(ta, a.samples[std::size_t(i)], tb, b.samples[std::size_t(k)])) {
                if (hit) *hit = {i, k};
                found = true;
                break;
            }
        }
    }
    if (stats) stats->samples += tested;
    if (!found && hit) *hit = {};
    return found;
}

bool collide_all_pairs(const Path& a, const Placement& pa, const Path& b, const Placement& pb) {
    const Rigid2 ta = Rigid2::of(pa), tb = Rigid2::of(pb);
    for (std::size_t i = 0; i < a.size(); ++i)
        for (std::size_t k = 0; k < b.size(); ++k)
            if (times_overlap(sample_time(pa, a.dt, std::int64_t(i)), sample_time(pa, a.dt, std::int64_t(i) + 1),
                              sample_time(pb, b.dt, std::int64_t(k)), sample_time(pb, b.dt, std::int64_t(k) + 1)) &&
                samples_overlap(ta, a.samples[i], tb, b.samples[k]))
                return true;
    return false;
}

}  // namespace mobb
