#include "mobb/core/scan.h"

#include "pair_kernel.h"

namespace mobb {

bool collide_scan(const ClipIndex& a, const Placement& pa, const ClipIndex& b, const Placement& pb, SamplePair* hit) {
    if (hit) *hit = {};
    detail::PairQuery q(a, pa, b, pb, hit);
    if (!q.passes_root_test()) return false;
    detail::Diagonals diag;
    if (!detail::diagonals(q, diag)) return detail::general_scan(q);
    for (int k = 0; k < diag.count; ++k)
        if (q.scan_diagonal(diag.d[k], diag.lo[k], diag.hi[k])) return true;
    return false;
}

}  // namespace mobb
