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

namespace {

// Lowers a's and b's entries to the gaps between their samples that overlap in time.
void lower_pair(const Path& a, const Placement& pa, const Path& b, const Placement& pb, std::vector<double>& ga,
                std::vector<double>& gb) {
    const Rigid2 ta = Rigid2::of(pa), tb = Rigid2::of(pb);
    for (std::int64_t i = 0; i < std::int64_t(a.size()); ++i) {
        const double s0 = sample_time(pa, a.dt, i), s1 = sample_time(pa, a.dt, i + 1);
        const Sample& p = a.samples[std::size_t(i)];
        const SampleRange w = aligned_samples(s0, s1, pb, b.dt, std::int64_t(b.size()));
        for (std::int64_t k = w.k0; k <= w.k1; ++k) {
            if (!times_overlap(s0, s1, sample_time(pb, b.dt, k), sample_time(pb, b.dt, k + 1))) continue;
            const double gap = samples_gap(ta, p, tb, b.samples[std::size_t(k)]);
            double& x = ga[std::size_t(i)];
            double& y = gb[std::size_t(k)];
            if (gap < x) x = gap;
            if (gap < y) y = gap;
        }
    }
}

}  // namespace

std::vector<std::vector<double>> nearest_clearance(const std::vector<const Path*>& paths,
                                                   const std::vector<Placement>& places) {
    const double inf = std::numeric_limits<double>::infinity();
    std::vector<std::vector<double>> out;
    out.reserve(paths.size());
    for (const Path* p : paths) out.emplace_back(p->size(), inf);
    for (std::size_t c = 0; c < paths.size(); ++c) {
        const Path& a = *paths[c];
        const double a0 = places[c].t0, a1 = sample_time(places[c], a.dt, std::int64_t(a.size()));
        for (std::size_t d = c + 1; d < paths.size(); ++d) {
            const Path& b = *paths[d];
            const double b0 = places[d].t0, b1 = sample_time(places[d], b.dt, std::int64_t(b.size()));
            if (times_overlap(a0, a1, b0, b1)) lower_pair(a, places[c], b, places[d], out[c], out[d]);
        }
    }
    return out;
}

}  // namespace mobb
