// Private to the core: the pieces shared by collide_scan() and collide_sweep(). One query's setup
// (relative frame, rounding margin, time diagonals), a 4-wide float filter of sample pairs that may
// only err towards "candidate", and the exact confirmation of a candidate.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "mobb/core/clip_index.h"
#include "mobb/core/obb.h"
#include "mobb/core/query.h"

namespace mobb::detail {

/// cos x and sin x to within kApproxCosSinError each, for |x| <= 1e6 (else false): Cody-Waite
/// reduction by pi/2 (fdlibm's 33-bit pio2_1 and its tail, so k * pio2_1 is exact; the reduced
/// argument is off by under 1e-15) and Taylor polynomials on [-pi/4, pi/4] to r^9 and r^10
/// (truncation below 1.8e-9 and 1.2e-10). Cheaper than std::cos and std::sin, but not the same
/// values: only for the root test and the filters, whose margins take the error in (PairQueryT's
/// Lazy constructor, rel_error).
inline constexpr double kApproxCosSinError = 1e-8;
inline bool approx_cos_sin(double x, double& c, double& s) {
    if (!(std::abs(x) <= 1e6)) return false;
    constexpr double kTwoOverPi = 0.63661977236758134308, kRound = 0x1.8p52;
    constexpr double kPio2Hi = 1.57079632673412561417e+00, kPio2Lo = 6.07710050650619224932e-11;
    const double k = (x * kTwoOverPi + kRound) - kRound;  // nearest integer (round-to-nearest mode)
    const double r = (x - k * kPio2Hi) - k * kPio2Lo, r2 = r * r;
    const double sr = r + r * r2 * (-1.0 / 6 + r2 * (1.0 / 120 + r2 * (-1.0 / 5040 + r2 * (1.0 / 362880))));
    const double cr =
        1 + r2 * (-0.5 + r2 * (1.0 / 24 + r2 * (-1.0 / 720 + r2 * (1.0 / 40320 + r2 * (-1.0 / 3628800)))));
    switch (std::int64_t(k) & 3) {
        case 0: c = cr, s = sr; break;
        case 1: c = -sr, s = cr; break;
        case 2: c = -cr, s = -sr; break;
        default: c = sr, s = -cr; break;
    }
    return true;
}

/// One query: B's local frame expressed in A's (float, for filters), the filter margin (metres),
/// and the world transforms the exact test uses. kLazy (the circle sweep's): the rotations may be
/// approximate until a candidate needs the exact test (the Lazy constructor); without it (the best
/// scan's) they are always exact and the code is the scan's as measured before.
template <bool kLazy>
struct PairQueryT {
    struct Lazy {};

    const ClipIndex& a;
    const ClipIndex& b;
    const Placement& pa;
    const Placement& pb;
    SamplePair* hit;
    mutable Rigid2 ta, tb;
    SpaceTimeRigid rel;  // double, for the root box test
    float c = 1, s = 0, tx = 0, ty = 0, margin = 0;
    // Bound on the error of rel's rotation and shift from approximate cos/sin (0 when exact), as a
    // length: rel applied to any point of B's box or samples is off by at most rel_error metres.
    double rel_error = 0;
    mutable bool exact_frames = true;  // ta and tb hold Rigid2::of(pa) and Rigid2::of(pb)

    PairQueryT(const ClipIndex& ia, const Placement& qa, const ClipIndex& ib, const Placement& qb, SamplePair* h)
        : PairQueryT(ia, qa, Rigid2::of(qa), ib, qb, Rigid2::of(qb), h) {}
    /// With the rotations of the placements given (Rigid2::of(qa), Rigid2::of(qb)).
    PairQueryT(const ClipIndex& ia, const Placement& qa, const Rigid2& ra, const ClipIndex& ib, const Placement& qb,
               const Rigid2& rb, SamplePair* h)
        : a(ia), b(ib), pa(qa), pb(qb), hit(h), ta(ra), tb(rb) {
        set_relative();
    }
    /// Rotations evaluated only when a candidate pair needs the exact test: the root test and the
    /// filters use approx_cos_sin() with rel_error in their margins, so most queries that end
    /// without a candidate never call std::cos / std::sin. Angles beyond 1e6 rad: exact at once.
    PairQueryT(const ClipIndex& ia, const Placement& qa, const ClipIndex& ib, const Placement& qb, SamplePair* h, Lazy)
        : a(ia), b(ib), pa(qa), pb(qb), hit(h) {
        static_assert(kLazy, "the lazy constructor is the circle sweep's");
        if (!approx_cos_sin(qa.theta, ta.c, ta.s) || !approx_cos_sin(qb.theta, tb.c, tb.s)) {
            ta = Rigid2::of(qa), tb = Rigid2::of(qb);
            set_relative();
            return;
        }
        ta.tx = qa.x, ta.ty = qa.y, tb.tx = qb.x, tb.ty = qb.y;
        exact_frames = false;
        set_relative();
        // Each of ta.c, ta.s, tb.c, tb.s is off by at most e = kApproxCosSinError: rel.c and rel.s by
        // 4e (plus rounding), the shift by 2e (|dx| + |dy|); a point p of B (|p.x| + |p.y| <= the box's
        // or the samples' reach, max_abs + max_radius + the box's fit margin) by 8e |p| + 2e (|dx| + |dy|).
        // Taken 10x wider.
        const double reach = 2 * (ib.max_abs() + ib.max_radius()) + 1;
        rel_error = 10 * kApproxCosSinError * (8 * reach + 2 * (std::abs(qb.x - qa.x) + std::abs(qb.y - qa.y)));
    }

    void set_relative() {
        // R_a^T R_b and R_a^T (t_b - t_a), from the very cos/sin the exact test uses (or their
        // approximations, lazy).
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
        if constexpr (kLazy) {
            if (!root_boxes_overlap()) return false;
        } else {
            if (!overlap(a.root_box(), transformed(b.root_box(), rel))) return false;
        }
        // Float rounding of inputs, frame and arithmetic is below 2^-20 of this scale; the double
        // rounding of the exact world-frame test below 2^-50 of the world coordinates.
        const double scale =
            a.max_abs() + b.max_abs() + std::abs(rel.shift.x) + std::abs(rel.shift.y) + a.max_radius() + b.max_radius();
        const double world = std::abs(pa.x) + std::abs(pa.y) + std::abs(pb.x) + std::abs(pb.y);
        margin = float(scale * 0x1p-18 + (world + scale) * 0x1p-40 + (kLazy ? rel_error : 0.0));
        c = float(rel.c), s = float(rel.s), tx = float(rel.shift.x), ty = float(rel.shift.y);
        return true;
    }

    // The root boxes' separating-axis test (as overlap(Obb2, Obb2)) written out in A's frame: B's box
    // rotated by rel, its half extents grown by rel_error. The four axes' projections share the two
    // numbers cos and sin of the angle between the boxes' axes.
    bool root_boxes_overlap() const {
        const Obb2 &ba = a.root_box(), &bb = b.root_box();
        const double ux = rel.c * bb.axis.x - rel.s * bb.axis.y, uy = rel.s * bb.axis.x + rel.c * bb.axis.y;
        const double cx = rel.c * bb.center.x - rel.s * bb.center.y + rel.shift.x - ba.center.x;
        const double cy = rel.s * bb.center.x + rel.c * bb.center.y + rel.shift.y - ba.center.y;
        const double ax = ba.axis.x, ay = ba.axis.y, hx = bb.half.x + rel_error, hy = bb.half.y + rel_error;
        const double cs = std::abs(ax * ux + ay * uy), sn = std::abs(ax * uy - ay * ux);
        return !(std::abs(cx * ax + cy * ay) > ba.half.x + hx * cs + hy * sn ||
                 std::abs(cy * ax - cx * ay) > ba.half.y + hx * sn + hy * cs ||
                 std::abs(cx * ux + cy * uy) > hx + ba.half.x * cs + ba.half.y * sn ||
                 std::abs(cy * ux - cx * uy) > hy + ba.half.x * sn + ba.half.y * cs);
    }

    // The exact predicate on one pair: time on sample_time(), space by samples_overlap().
    bool exact(std::int64_t i, std::int64_t j) const {
        const double dta = a.path().dt, dtb = b.path().dt;
        if (!times_overlap(sample_time(pa, dta, i), sample_time(pa, dta, i + 1), sample_time(pb, dtb, j),
                           sample_time(pb, dtb, j + 1)))
            return false;
        if constexpr (kLazy) {
            if (!exact_frames) ta = Rigid2::of(pa), tb = Rigid2::of(pb), exact_frames = true;
        }
        if (!samples_overlap(ta, a.path().samples[std::size_t(i)], tb, b.path().samples[std::size_t(j)])) return false;
        if (hit) *hit = {i, j};
        return true;
    }

    // Circle i of A and circle j of B (moved into A's frame) may overlap: never false for blocks
    // holding a colliding pair (the margin covers float rounding).
    bool circles_overlap(const Circles& ca, std::int64_t i, const Circles& cb, std::int64_t j) const {
        const float bx = cb.x[j], by = cb.y[j];
        const float qx = c * bx - s * by + tx, qy = s * bx + c * by + ty;
        const float dx = ca.x[i] - qx, dy = ca.y[i] - qy, rr = ca.r[i] + cb.r[j] + margin;
        return dx * dx + dy * dy < rr * rr;
    }

    // Bit k set when pair (i + k, j + k), k < 4, may collide. Branch-free.
    unsigned filter4(std::int64_t i, std::int64_t j) const {
        return discs4(a.xs() + i, a.ys() + i, a.rs() + i, b.xs() + j, b.ys() + j, b.rs() + j);
    }

    // Bit k set when circles i + k of A and j + k of B may overlap, k < 4. Branch-free.
    unsigned circles4(const Circles& ca, std::int64_t i, const Circles& cb, std::int64_t j) const {
        return discs4(ca.x + i, ca.y + i, ca.r + i, cb.x + j, cb.y + j, cb.r + j);
    }

    // Bit k set when disc k of A (ax, ay, ar) and disc k of B, moved into A's frame, may overlap.
    unsigned discs4(const float* ax, const float* ay, const float* ar, const float* bx, const float* by,
                    const float* br) const {
#if defined(__SSE2__)
        const __m128 vc = _mm_set1_ps(c), vs = _mm_set1_ps(s), vm = _mm_set1_ps(margin);
        const __m128 x = _mm_loadu_ps(bx), y = _mm_loadu_ps(by);
        const __m128 qx = _mm_add_ps(_mm_sub_ps(_mm_mul_ps(vc, x), _mm_mul_ps(vs, y)), _mm_set1_ps(tx));
        const __m128 qy = _mm_add_ps(_mm_add_ps(_mm_mul_ps(vs, x), _mm_mul_ps(vc, y)), _mm_set1_ps(ty));
        const __m128 dx = _mm_sub_ps(_mm_loadu_ps(ax), qx), dy = _mm_sub_ps(_mm_loadu_ps(ay), qy);
        const __m128 rr = _mm_add_ps(_mm_add_ps(_mm_loadu_ps(ar), _mm_loadu_ps(br)), vm);
        const __m128 d2 = _mm_add_ps(_mm_mul_ps(dx, dx), _mm_mul_ps(dy, dy));
        return unsigned(_mm_movemask_ps(_mm_cmplt_ps(d2, _mm_mul_ps(rr, rr))));
#else
        unsigned mask = 0;
        for (int k = 0; k < 4; ++k) {
            const float qx = c * bx[k] - s * by[k] + tx, qy = s * bx[k] + c * by[k] + ty;
            const float dx = ax[k] - qx, dy = ay[k] - qy, rr = ar[k] + br[k] + margin;
            mask |= unsigned(dx * dx + dy * dy < rr * rr) << k;
        }
        return mask;
#endif
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
template <class Query>
bool diagonals(const Query& q, Diagonals& out) {
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

/// The same set of diagonals for the circle sweep, computed with fewer steps: ceil and floor by
/// truncation (|delta| < na + nb + 4 < 2^23), the best-overlapping diagonal first and the others in
/// ascending order (the order only decides which colliding pair is found first).
inline bool sweep_diagonals(const PairQueryT<true>& q, Diagonals& out) {
    const double dt = q.a.path().dt;
    if (dt != q.b.path().dt) return false;
    const auto na = std::int64_t(q.a.size()), nb = std::int64_t(q.b.size());
    const double delta = (q.pa.t0 - q.pb.t0) / dt;
    const double eps = ((std::abs(q.pa.t0) + std::abs(q.pb.t0)) / dt + double(na + nb + 2) + std::abs(delta)) * 0x1p-46;
    if (!(eps < 0.25) || !(std::abs(delta) < double(na + nb + 4))) return false;
    const double lo_r = delta - 1 - eps, hi_r = delta + 1 + eps;
    std::int64_t dmin = std::int64_t(lo_r), dmax = std::int64_t(hi_r);
    dmin += double(dmin) < lo_r;  // ceil
    dmax -= double(dmax) > hi_r;  // floor
    double best = 2;
    for (std::int64_t d = dmin; d <= dmax; ++d) {
        const std::int64_t lo = std::max<std::int64_t>(0, -d), hi = std::min(na, nb - d);
        if (lo >= hi) continue;
        const int k = out.count++;
        out.d[k] = d, out.lo[k] = lo, out.hi[k] = hi;
        if (const double off = std::abs(double(d) - delta); off < best) {
            best = off;
            std::swap(out.d[k], out.d[0]);
            std::swap(out.lo[k], out.lo[0]);
            std::swap(out.hi[k], out.hi[0]);
        }
    }
    out.dmin = dmin, out.dmax = dmax;
    return true;
}

/// Different sample spacings: the exact two-pointer walk shared with the trees' leaves.
template <bool kLazy>
bool general_scan(const PairQueryT<kLazy>& q) {
    if constexpr (kLazy) {
        if (!q.exact_frames) q.ta = Rigid2::of(q.pa), q.tb = Rigid2::of(q.pb), q.exact_frames = true;
    }
    std::uint64_t tested = 0;
    SamplePair h;
    const bool found = leaf_test(q.a.path(), q.pa, q.ta, 0, std::int64_t(q.a.size()), q.b.path(), q.pb, q.tb, 0,
                                 std::int64_t(q.b.size()), tested, h);
    if (found && q.hit) *q.hit = h;
    return found;
}

/// The best scan's query (collide_scan) and the circle sweep's (collide_sweep).
using PairQuery = PairQueryT<false>;
using SweepQuery = PairQueryT<true>;

}  // namespace mobb::detail
