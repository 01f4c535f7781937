// The circle sweep: the library's default exact query (the crowd's narrow phase and Python's
// mobb.collide on clip indexes), the same answer as collide() and collide_brute().
#pragma once
#include "mobb/core/clip_index.h"
#include "mobb/core/path.h"
#include "mobb/core/query.h"

namespace mobb {

/// Do placed clips a and b collide (README "model": some time-overlapping sample pair with
/// |p_a,i - p_b,j| < r_a,i + r_b,j)? Exactly the answer of collide_brute(a.path(), pa, b.path(), pb).
/// Plan: clip time ranges first; the root MOBB test (double); then, when both clips share one
/// sample spacing, only the time-aligned diagonals j - i = d that can overlap are visited. A short
/// overlap (at most 200 time-aligned pairs: the crowd's clips) is swept at the leaves: A's blocks of
/// 16 samples against the B blocks time aligned with them by bounding circles (clip_index.h), four
/// at a time; a long one at two levels: blocks of 32 samples in chunks of 512 samples first tested
/// whole. Only blocks that may collide are scanned, 4-wide filtered pairs (float, rounded outward).
/// Every candidate is confirmed by times_overlap on sample_time() and samples_overlap() in double,
/// so rounding can only cost time. Different sample spacings use an exact two-pointer scan instead.
/// (The paper's trees, section 3, bound with boxes and recurse; this flat sweep is the same bounding
/// idea laid out for SIMD: bench/results/log.md.)
/// This overload evaluates std::cos / std::sin of the placements only when a candidate pair needs
/// the exact test: the root test and the filters rotate with a polynomial approximation (within
/// 1e-8, angles up to 1e6 rad; beyond, the exact rotations at once) whose error is added to their
/// margins. Most non-colliding queries then end without the two library calls, which were a fifth
/// of a short query's instructions; this and the leaf blocks make it at least as fast as the best
/// scan (scan.h) on short clips too (bench/results/log.md, 2026-11-25).
/// On a hit, stores a colliding pair in `hit` (not necessarily the one brute force reports).
bool collide_sweep(const ClipIndex& a, const Placement& pa, const ClipIndex& b, const Placement& pb,
                   SamplePair* hit = nullptr);
/// The same with the placements' rotations given, ta == Rigid2::of(pa) and tb == Rigid2::of(pb): a
/// caller querying one placed clip against many computes each once (the crowd's choice points); no
/// approximation is then needed.
bool collide_sweep(const ClipIndex& a, const Placement& pa, const Rigid2& ta, const ClipIndex& b, const Placement& pb,
                   const Rigid2& tb, SamplePair* hit = nullptr);

}  // namespace mobb
