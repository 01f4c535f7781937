// Private to the core: the best scan's query (collide_scan). One query's setup (relative frame,
// rounding margin, time diagonals), a 4-wide float filter of sample pairs that may only err towards
// "candidate", and the exact confirmation of a candidate. (The circle sweep has its own:
// sweep_query.h.)
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "disc_filter.h"
#include "mobb/core/clip_index.h"
#include "mobb/core/obb.h"
#include "mobb/core/query.h"

namespace mobb::detail {

/// One query: B's local frame expressed in A's (float, for the filters: DiscFilter, set by
/// passes_root_test()) with the filter margin (metres), and the world transforms the exact test uses.
struct PairQuery : DiscFilter {
    const ClipIndex& a;
    const ClipIndex& b;
    const Placement& pa;
    const Placement& pb;
    SamplePair* hit;
    Rigid2 ta, tb;
    SpaceTimeRigid rel;  // double, for the root box test

    PairQuery(const ClipIndex& ia, const Placement& qa, const ClipIndex& ib, const Placement& qb, SamplePair* h)
        : a(ia), b(ib), pa(qa), pb(qb), hit(h), ta(Rigid2::of(qa)), tb(Rigid2::of(qb)) {
        set_relative();
    }
    void set_relative() {
        // R_a^T R_b and R_a^T (t_b - t_a), from the very cos/sin the exact test uses.
        rel.c = ta.c * tb.c + ta.s * tb.s;
        rel.s = ta.c * tb.s - ta.s * tb.c;
        const double dx = tb.tx - ta.tx, dy = tb.ty - ta.ty;
        rel.shift = {ta.c * dx + ta.s * dy, -ta.s * dx + ta.c * dy, 0.0};
    }

    // Temporal pruning, then the 1-level root box test. Fills the float frame when both pass.
    bool passes_root_test() {
        const double dta = a.path().dt, dtb = b.path().dt;
        const auto na = std::int64_t(a.size()), nb = std::int64_t(b.size());
        if (!times_overlap(sample_time(pa, dta, 0), sample_time(pa, dta, na), sample_time(pb, dtb, 0),
                           sample_time(pb, dtb, nb)))
            return false;
        if (!overlap(a.root_box(), transformed(b.root_box(), rel))) return false;
        // Float rounding of inputs, frame and arithmetic is below 2^-20 of this scale; the double
        // rounding of the exact world-frame test below 2^-50 of the world coordinates.
        const double scale =
            a.max_abs() + b.max_abs() + std::abs(rel.shift.x) + std::abs(rel.shift.y) + a.max_radius() + b.max_radius();
        const double world = std::abs(pa.x) + std::abs(pa.y) + std::abs(pb.x) + std::abs(pb.y);
        margin = float(scale * 0x1p-18 + (world + scale) * 0x1p-40);
        c = float(rel.c), s = float(rel.s), tx = float(rel.shift.x), ty = float(rel.shift.y);
        return true;
    }

    // The exact predicate on one pair: time on sample_time(), space by samples_overlap().
    bool exact(std::int64_t i, std::int64_t j) const {
        const double dta = a.path().dt, dtb = b.path().dt;
        if (!times_overlap(sample_time(pa, dta, i), sample_time(pa, dta, i + 1), sample_time(pb, dtb, j),
                           sample_time(pb, dtb, j + 1)))
            return false;
        if (!samples_overlap(ta, a.path().samples[std::size_t(i)], tb, b.path().samples[std::size_t(j)])) return false;
        if (hit) *hit = {i, j};
        return true;
    }

    // Bit k set when pair (i + k, j + k), k < 4, may collide. Branch-free.
    unsigned filter4(std::int64_t i, std::int64_t j) const {
        return discs4(a.xs() + i, a.ys() + i, a.rs() + i, b.xs() + j, b.ys() + j, b.rs() + j);
    }

    // Pairs (i, i + d) for i in [lo, hi), in blocks of 16 filtered pairs with one early-exit branch
    // each; candidates confirmed exactly in order.
    bool scan_diagonal(std::int64_t d, std::int64_t lo, std::int64_t hi) const {
        for (std::int64_t i = lo; i < hi; i += 16) {
            unsigned mask = filter4(i, i + d) | filter4(i + 4, i + 4 + d) << 4 | filter4(i + 8, i + 8 + d) << 8 |
                            filter4(i + 12, i + 12 + d) << 12;
            if (hi - i < 16) mask &= (1u << unsigned(hi - i)) - 1u;
            while (mask) {
                const int k = __builtin_ctz(mask);
                if (exact(i + k, i + k + d)) return true;
                mask &= mask - 1;
            }
        }
        return false;
    }
};

/// Time diagonals for equal sample spacing: pair (i, j = i + d) can overlap in time only for d in
/// `d[0..count)`, ordered by how much they overlap (most first), each with its valid i in [lo, hi).
struct Diagonals {
    std::int64_t d[3] = {0, 0, 0}, lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    int count = 0;
    std::int64_t dmin = 0, dmax = 0;  ///< range of d over the candidates (valid when count > 0)
};

/// False when the spacings differ or the offsets are too large to reason about arithmetically
/// (then callers use the two-pointer leaf_test). In reals, pair (i, i + d) overlaps iff
/// |d - delta| < 1, delta = (t0_a - t0_b) / dt; the window is widened by a bound on the rounding of
/// sample_time() so the exact check, not this arithmetic, decides every pair.
inline bool diagonals(const PairQuery& q, Diagonals& out) {
    const double dt = q.a.path().dt;
    if (dt != q.b.path().dt) return false;
    const auto na = std::int64_t(q.a.size()), nb = std::int64_t(q.b.size());
    const double delta = (q.pa.t0 - q.pb.t0) / dt;
    const double eps = ((std::abs(q.pa.t0) + std::abs(q.pb.t0)) / dt + double(na + nb + 2) + std::abs(delta)) * 0x1p-46;
    if (!(eps < 0.25) || !(std::abs(delta) < double(na + nb + 4))) return false;
    const auto dmin = std::int64_t(std::ceil(delta - 1 - eps)), dmax = std::int64_t(std::floor(delta + 1 + eps));
    for (std::int64_t d = dmin; d <= dmax; ++d) {
        const std::int64_t lo = std::max<std::int64_t>(0, -d), hi = std::min(na, nb - d);
        if (lo >= hi) continue;
        int k = out.count++;
        out.d[k] = d, out.lo[k] = lo, out.hi[k] = hi;
        // Insertion by |d - delta|: the fully overlapping diagonal first, touching ones last.
        for (; k > 0 && std::abs(double(out.d[k]) - delta) < std::abs(double(out.d[k - 1]) - delta); --k) {
            std::swap(out.d[k], out.d[k - 1]);
            std::swap(out.lo[k], out.lo[k - 1]);
            std::swap(out.hi[k], out.hi[k - 1]);
        }
    }
    out.dmin = dmin, out.dmax = dmax;
    return true;
}

/// Different sample spacings: the exact two-pointer walk shared with the trees' leaves.
inline bool general_scan(const PairQuery& q) {
    std::uint64_t tested = 0;
    SamplePair h;
    const bool found = leaf_test(q.a.path(), q.pa, q.ta, 0, std::int64_t(q.a.size()), q.b.path(), q.pb, q.tb, 0,
                                 std::int64_t(q.b.size()), tested, h);
    if (found && q.hit) *q.hit = h;
    return found;
}

}  // namespace mobb::detail
