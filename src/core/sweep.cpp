#include "mobb/core/sweep.h"

#include "pair_kernel.h"

namespace mobb {

namespace {

// At most this many time-aligned pairs: A's leaf blocks (16 samples) are tested against B's by
// their circles and only the runs that may collide are scanned (leaf_sweep); above it, the two-level
// sweep of 32-sample blocks in 512-sample chunks. Leaf blocks on the crowd's short clips (table1,
// 36 samples per clip) cut its instructions by 4 % against scanning every pair (1,118 -> 1,073,
// callgrind, bench/callgrind_workload.sh) and table2's by 5 % (1,453 -> 1,379); 200 pairs make at
// most 14 leaf blocks of A, so one 32-bit mask holds them.
constexpr std::int64_t kLeafSweepPairs = 200;
// Sweep blocks: level 1 of the hierarchy (32 samples), in chunks of 16 (one level-5 block, 512
// samples) whose own circle is tested first. Chosen by callgrind instruction counts on table2,
// synth42 and synth120: 1,318 / 1,217 / 1,282; blocks of 64 with 512-sample chunks 1,508 / 1,316 /
// 1,297; blocks of 16 with 256-sample chunks 1,290 / 1,239 / 1,469; 32 with 256 or 1,024 between.
constexpr int kSweepLevel = 1;
constexpr int kChunkLevel = 5;
constexpr int kSweepShift = ClipIndex::kLeafShift + kSweepLevel;
constexpr std::int64_t kChunk = std::int64_t(1) << (kChunkLevel - kSweepLevel);
// More pairs than this over at most three diagonals: both clips have sweep blocks (level 1).
static_assert(kLeafSweepPairs >= 3 << kSweepShift);

// Floor of v / 2^shift for either sign.
std::int64_t floor_shift(std::int64_t v, int shift) {
    return v >= 0 ? v >> shift : -((-v + (std::int64_t(1) << shift) - 1) >> shift);
}

// May A's chunk (block `chunk` of level kChunkLevel) collide with B? Its circle against those of B's
// blocks at the same level (or B's top) holding its time-aligned partners.
bool chunk_near(const detail::SweepQuery& q, const detail::Diagonals& diag, std::int64_t chunk) {
    if (q.a.levels() <= kChunkLevel + 1) return true;  // one chunk: the root test already passed
    const auto na = std::int64_t(q.a.size()), nb = std::int64_t(q.b.size());
    const int shift = ClipIndex::kLeafShift + kChunkLevel;
    const std::int64_t f = chunk << shift, e = std::min((chunk + 1) << shift, na);
    const int kb = std::min(kChunkLevel, q.b.levels() - 1);
    const int shift_b = ClipIndex::kLeafShift + kb;
    const std::int64_t g0 = std::max<std::int64_t>(0, f + diag.dmin) >> shift_b;
    const std::int64_t g1 = (std::min(nb, e + diag.dmax) - 1) >> shift_b;
    const Circles ca = q.a.level(kChunkLevel), cb = q.b.level(kb);
    for (std::int64_t g = g0; g <= g1; ++g)
        if (q.circles_overlap(ca, chunk, cb, g)) return true;
    return false;
}

// A's sweep blocks in the time overlap against B's, chunk by chunk in time order. As both clips'
// blocks start at sample 0, the B blocks holding the partners of A's block k are k + o for a few
// constant offsets o (dmin and dmax of the diagonals, in blocks), so a chunk's blocks are tested
// four at a time without branches; then the blocks that may collide are scanned, earlier first.
bool sweep(const detail::SweepQuery& q, const detail::Diagonals& diag) {
    std::int64_t ilo = std::int64_t(q.a.size()), ihi = 0;
    for (int k = 0; k < diag.count; ++k) ilo = std::min(ilo, diag.lo[k]), ihi = std::max(ihi, diag.hi[k]);
    const std::int64_t k0 = ilo >> kSweepShift, k1 = ((ihi - 1) >> kSweepShift) + 1;
    const std::int64_t o0 = floor_shift(diag.dmin, kSweepShift);
    const std::int64_t o1 = floor_shift(diag.dmax + (std::int64_t(1) << kSweepShift) - 1, kSweepShift);
    const Circles ca = q.a.level(kSweepLevel), cb = q.b.level(kSweepLevel);
    const auto nbb = std::int64_t(cb.count);
    for (std::int64_t c = k0 & ~(kChunk - 1); c < k1; c += kChunk) {
        if (!chunk_near(q, diag, c / kChunk)) continue;
        unsigned mask = 0;
        for (std::int64_t o = o0; o <= o1; ++o) {
            const std::int64_t lo = std::max({c, k0, -o}), hi = std::min({c + kChunk, k1, nbb - o});
            for (std::int64_t k = lo; k < hi; k += 4) {
                unsigned m = q.circles4(ca, k, cb, k + o);
                if (hi - k < 4) m &= (1u << unsigned(hi - k)) - 1u;
                mask |= m << unsigned(k - c);
            }
        }
        // A run of consecutive blocks is scanned as one range, so where nothing prunes the sweep
        // costs little more than the scan. (Runs carried across chunks scan later: more instructions.)
        while (mask) {
            const int first = __builtin_ctz(mask), len = __builtin_ctz(~(mask >> first));
            const std::int64_t f = (c + first) << kSweepShift, e = (c + first + len) << kSweepShift;
            for (int j = 0; j < diag.count; ++j) {
                const std::int64_t lo = std::max(f, diag.lo[j]), hi = std::min(e, diag.hi[j]);
                if (lo < hi && q.scan_diagonal(diag.d[j], lo, hi)) return true;
            }
            mask &= ~(((1u << len) - 1u) << first);
        }
    }
    return false;
}

// A short overlap: A's leaf blocks (16 samples) against the B leaf blocks holding their
// time-aligned partners, by bounding circles; the runs of blocks that may collide are scanned.
bool leaf_sweep(const detail::SweepQuery& q, const detail::Diagonals& diag) {
    constexpr int shift = ClipIndex::kLeafShift;
    std::int64_t ilo = std::int64_t(q.a.size()), ihi = 0;
    for (int k = 0; k < diag.count; ++k) ilo = std::min(ilo, diag.lo[k]), ihi = std::max(ihi, diag.hi[k]);
    const std::int64_t k0 = ilo >> shift, k1 = ((ihi - 1) >> shift) + 1;
    const std::int64_t o0 = floor_shift(diag.dmin, shift);
    const std::int64_t o1 = floor_shift(diag.dmax + (std::int64_t(1) << shift) - 1, shift);
    const Circles ca = q.a.level(0), cb = q.b.level(0);
    const auto nbb = std::int64_t(cb.count);
    unsigned mask = 0;
    for (std::int64_t o = o0; o <= o1; ++o) {
        const std::int64_t lo = std::max(k0, -o), hi = std::min(k1, nbb - o);
        for (std::int64_t k = lo; k < hi; k += 4) {
            unsigned m = q.circles4(ca, k, cb, k + o);
            if (hi - k < 4) m &= (1u << unsigned(hi - k)) - 1u;
            mask |= m << unsigned(k - k0);
        }
    }
    while (mask) {
        const int first = __builtin_ctz(mask), len = __builtin_ctz(~(mask >> first));
        const std::int64_t f = (k0 + first) << shift, e = (k0 + first + len) << shift;
        for (int j = 0; j < diag.count; ++j) {
            const std::int64_t lo = std::max(f, diag.lo[j]), hi = std::min(e, diag.hi[j]);
            if (lo < hi && q.scan_diagonal(diag.d[j], lo, hi)) return true;
        }
        mask &= ~(((1u << len) - 1u) << first);
    }
    return false;
}

// The plan of collide_sweep() after the setup of q.
inline bool query(detail::SweepQuery& q) {
    if (!q.passes_root_test()) return false;
    detail::Diagonals diag;
    if (!detail::sweep_diagonals(q, diag)) return detail::general_scan(q);
    std::int64_t pairs = 0;
    for (int k = 0; k < diag.count; ++k) pairs += diag.hi[k] - diag.lo[k];
    if (pairs <= kLeafSweepPairs) return leaf_sweep(q, diag);
    return sweep(q, diag);
}

}  // namespace

bool collide_sweep(const ClipIndex& a, const Placement& pa, const ClipIndex& b, const Placement& pb, SamplePair* hit) {
    if (hit) *hit = {};
    detail::SweepQuery q(a, pa, b, pb, hit, detail::SweepQuery::Lazy{});
    return query(q);
}

bool collide_sweep(const ClipIndex& a, const Placement& pa, const Rigid2& ta, const ClipIndex& b, const Placement& pb,
                   const Rigid2& tb, SamplePair* hit) {
    if (hit) *hit = {};
    detail::SweepQuery q(a, pa, ta, b, pb, tb, hit);
    return query(q);
}

}  // namespace mobb
