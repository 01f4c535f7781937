// The brute-force reference: direct evaluation of the collision predicate, the tests' oracle.
#pragma once
#include "mobb/core/path.h"
#include "mobb/core/query.h"

namespace mobb {

/// Same answer as collide() by definition: for every sample i of a, tests every sample j of b whose
/// time interval could overlap (an arithmetic window widened by two samples each side, then the
/// exact predicate). No boxes, no search structure. O(n + m) for equal sample spacings.
bool collide_brute(const Path& a, const Placement& pa, const Path& b, const Placement& pb, QueryStats* stats = nullptr,
                   SamplePair* hit = nullptr);

/// Every pair (i, j), O(n m): the reference for the reference, for short paths.
bool collide_all_pairs(const Path& a, const Placement& pa, const Path& b, const Placement& pb);

}  // namespace mobb
