// Yes/no space-time collision queries between two placed trees (paper section 3.2).
#pragma once
#include <cstdint>

#include "mobb/core/path.h"
#include "mobb/core/trace.h"
#include "mobb/core/tree.h"

namespace mobb {

/// Work done by queries: the columns of the paper's Table 1. Adds up over calls.
struct QueryStats {
    std::uint64_t tests2d = 0;  ///< 2D box separating-axis tests
    std::uint64_t tests3d = 0;  ///< 3D box separating-axis tests (also 2D-vs-3D pairs)
    std::uint64_t samples = 0;  ///< sample-sample distance tests
};

/// A colliding sample pair (indices into each path).
struct SamplePair {
    std::int64_t a = -1, b = -1;
};

/// Do placed clips a and b ever bring their characters closer than r_a + r_b at the same time?
/// True iff some samples i, j have time intervals overlapping with positive length and
/// |p_a,i - p_b,j| < r_a,i + r_b,j (see path.h). Exits at the first hit. Trees of any types and
/// sample spacings may be mixed. Counting and tracing cost nothing when stats / trace are null;
/// a non-null trace is cleared and filled with the ordered events.
bool collide(const Tree& a, const Placement& pa, const Tree& b, const Placement& pb, QueryStats* stats = nullptr,
             Trace* trace = nullptr, SamplePair* hit = nullptr);

/// The leaf test shared by every tree and the 1-level baseline: binary search in time for the first
/// overlapping samples of a[fa, ea) and b[fb, eb), then walk the time-aligned pairs. Counts sample
/// tests into `tested`; on a hit stores the pair and returns true.
bool leaf_test(const Path& a, const Placement& pa, const Rigid2& ta, std::int64_t fa, std::int64_t ea, const Path& b,
               const Placement& pb, const Rigid2& tb, std::int64_t fb, std::int64_t eb, std::uint64_t& tested,
               SamplePair& hit);

}  // namespace mobb
