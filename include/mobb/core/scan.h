// "Best scan": the paper's 1-level idea written for speed, the strongest simple peer of the trees.
#pragma once
#include "mobb/core/clip_index.h"
#include "mobb/core/path.h"
#include "mobb/core/query.h"

namespace mobb {

/// Same answer as collide_brute(a.path(), pa, b.path(), pb). Clip time ranges, the root MOBB test,
/// then every time-aligned sample pair in order of time: for equal sample spacings the pairs lie on
/// at most three diagonals j - i = d, filtered 4 pairs at a time in float with an outward margin
/// (branch-free), one early-exit check per block of 16 pairs; candidates are confirmed exactly
/// (times_overlap on sample_time(), then samples_overlap()). Different spacings: two-pointer scan.
bool collide_scan(const ClipIndex& a, const Placement& pa, const ClipIndex& b, const Placement& pb,
                  SamplePair* hit = nullptr);

}  // namespace mobb
