#include "mobb/core/fast_query.h"

#include "pair_kernel.h"

namespace mobb {

namespace {

// At most this many time-aligned pairs: scanning them beats descending. 200 covers every crowd
// query (clips of ~60 samples: up to ~180 pairs over the candidate diagonals), where the scan's high
// IPC ties collide_scan in time (48: 1.26x slower); on the longest clips 200 costs as many
// instructions as 48, 600 costs 6 % more there and 20 % more on 42 s sequences (callgrind,
// bench/crowd_callgrind.sh; times: micro_bench Issue5 interleaved).
constexpr std::int64_t kScanPairs = 200;
// A block at this level or below that may collide is scanned rather than split further: blocks
// of 32 samples (fewer instructions per query than descending to 16 or scanning at 64, callgrind).
constexpr int kScanLevel = 1;
// Below this level blocks are tested as tubes (relative motion: tighter, prunes side-by-side
// walks), above as circles (cheaper; on the CMU sequences about as tight). Chosen by callgrind
// instruction counts on bench/'s 42 s workload (all tubes, all circles, 2 or 3 tube levels).
constexpr int kTubeLevels = 2;

// A's block hierarchy against B's at the same level: an A block is tested against each B block
// holding its time-aligned partners (at most three), on every candidate diagonal at once; a block
// that may collide is split, or scanned at kScanLevel. Iterative, depth first, earlier time first.
// (Starting lower than the top level, where tests nearly always pass, measured worse.)
bool descend(const detail::PairQuery& q, const detail::Diagonals& diag) {
    const ClipIndex& a = q.a;
    const ClipIndex& b = q.b;
    const auto na = std::int64_t(a.size()), nb = std::int64_t(b.size());
    std::int64_t ilo = na, ihi = 0;
    for (int k = 0; k < diag.count; ++k) ilo = std::min(ilo, diag.lo[k]), ihi = std::max(ihi, diag.hi[k]);

    struct Item {
        int level;
        std::int64_t block;
    };
    Item stack[64];  // depth-first: at most one pending sibling per level (< 22 levels)
    int top = 0;
    stack[top++] = {a.levels() - 1, 0};
    const int b_top = b.levels() - 1;
    while (top > 0) {
        const Item it = stack[--top];
        const int shift = ClipIndex::kLeafShift + it.level;
        const std::int64_t block_first = it.block << shift;
        const std::int64_t block_end = std::min((it.block + 1) << shift, na);
        const std::int64_t f = std::max(block_first, ilo), e = std::min(block_end, ihi);
        if (f >= e) continue;
        const Tube& ta = a.level(it.level)[std::size_t(it.block)];
        const std::int64_t ma2 = block_first + block_end - 1;
        const int kb = std::min(it.level, b_top);
        const int shift_b = ClipIndex::kLeafShift + kb;
        const std::vector<Tube>& lb = b.level(kb);
        const std::int64_t g0 = std::max<std::int64_t>(0, f + diag.dmin) >> shift_b;
        const std::int64_t g1 = (std::min(nb, e + diag.dmax) - 1) >> shift_b;
        bool near = false;
        if (it.level < kTubeLevels) {
            for (std::int64_t g = g0; g <= g1 && !near; ++g) {
                const std::int64_t bf = g << shift_b, be = std::min((g + 1) << shift_b, nb);
                const std::int64_t lo = std::max(f, bf - diag.dmax), hi = std::min(e, be - diag.dmin);
                near = lo < hi && q.tubes_overlap(ta, ma2, lb[std::size_t(g)], bf + be - 1, lo, hi, diag.dmin, diag.dmax);
            }
        } else {
            for (std::int64_t g = g0; g <= g1 && !near; ++g) near = q.circles_overlap(ta, lb[std::size_t(g)]);
        }
        if (!near) continue;
        if (it.level <= kScanLevel) {
            for (int k = 0; k < diag.count; ++k)
                if (q.scan_diagonal(diag.d[k], std::max(f, diag.lo[k]), std::min(e, diag.hi[k]))) return true;
            continue;
        }
        stack[top++] = {it.level - 1, 2 * it.block + 1};
        stack[top++] = {it.level - 1, 2 * it.block};
    }
    return false;
}

}  // namespace

bool collide_fast(const ClipIndex& a, const Placement& pa, const ClipIndex& b, const Placement& pb, SamplePair* hit) {
    if (hit) *hit = {};
    detail::PairQuery q(a, pa, b, pb, hit);
    if (!q.roots_overlap()) return false;
    detail::Diagonals diag;
    if (!detail::diagonals(q, diag)) return detail::general_scan(q);
    std::int64_t pairs = 0;
    for (int k = 0; k < diag.count; ++k) pairs += diag.hi[k] - diag.lo[k];
    if (pairs <= kScanPairs) {
        for (int k = 0; k < diag.count; ++k)
            if (q.scan_diagonal(diag.d[k], diag.lo[k], diag.hi[k])) return true;
        return false;
    }
    return descend(q, diag);
}

}  // namespace mobb
