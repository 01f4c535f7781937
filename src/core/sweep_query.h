// Private to the core: one query of the circle sweep (sweep.cpp). Its time window (the time-aligned
// diagonals), B's frame in A's (double for the root test, float for the filters) with the rounding
// margin, the 4-wide circle filter and the exact confirmation of a candidate pair.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "approx_rotation.h"
#include "disc_filter.h"
#include "mobb/core/clip_index.h"
#include "mobb/core/query.h"

namespace mobb::detail {

// B's frame in A's for the float filters, and their margin (DiscFilter): set_float_frame().
class SweepQuery : public DiscFilter {
public:
    const ClipIndex& a;
    const ClipIndex& b;
    const Placement& pa;
    const Placement& pb;
    SamplePair* hit;
    // Time-aligned diagonals, when both clips share one sample spacing (aligned()): pair (i, i + d)
    // can overlap in time only for d in [dmin, dmax] (at most three), centre = floor of their mean;
    // A's samples with a partner on one of them are [ilo, ihi).
    std::int64_t dmin, dmax, center, ilo, ihi;

    /// ra and rb: the placements' rotations (Rigid2::of(pa), Rigid2::of(pb)) when the caller has
    /// them, else null (computed only if a candidate pair needs the exact test).
    SweepQuery(const ClipIndex& ia, const Placement& qa, const Rigid2* ra, const ClipIndex& ib, const Placement& qb,
               const Rigid2* rb, SamplePair* h)
        : a(ia), b(ib), pa(qa), pb(qb), hit(h), given_a_(ra), given_b_(rb) {}

    /// Both clips share one sample spacing and the offsets are small enough to reason about
    /// arithmetically: fills the diagonals. Else false (then the exact two-pointer walk decides).
    /// In reals, pair (i, i + d) overlaps iff |d - delta| < 1, delta = (t0_a - t0_b) / dt; the window
    /// is widened by a bound on the rounding of sample_time() so the exact check, not this
    /// arithmetic, decides every pair. ceil and floor by truncation: |delta| < na + nb + 4 < 2^23.
    bool aligned() {
        const double dt = a.path().dt;
        if (dt != b.path().dt) return false;
        const auto na = std::int64_t(a.size()), nb = std::int64_t(b.size());
        const double delta = (pa.t0 - pb.t0) / dt;
        const double eps = ((std::abs(pa.t0) + std::abs(pb.t0)) / dt + double(na + nb + 2) + std::abs(delta)) * 0x1p-46;
        if (!(eps < 0.25) || !(std::abs(delta) < double(na + nb + 4))) return false;
        const double lo = delta - 1 - eps, hi = delta + 1 + eps;
        dmin = std::int64_t(lo), dmax = std::int64_t(hi);
        dmin += double(dmin) < lo;  // ceil
        dmax -= double(dmax) > hi;  // floor
        center = (dmin + dmax) >> 1;
        ilo = std::max<std::int64_t>(0, -dmax), ihi = std::min(na, nb - dmin);
        return true;
    }

    /// B's frame in A's for the root test and the filters: from the given rotations, else from
    /// approx_cos_sin2() with its error bounded as a length in rel_error_ (exact rotations when an
    /// angle is beyond its range).
    void set_relative() {
        if (given_a_) return set_relative(given_a_->c, given_a_->s, given_b_->c, given_b_->s, 0.0);
        double ca = 0, sa = 0, cb = 0, sb = 0;
        if (!approx_cos_sin2(pa.theta, pb.theta, ca, sa, cb, sb)) {
            const Rigid2 ra = Rigid2::of(pa), rb = Rigid2::of(pb);
            return set_relative(ra.c, ra.s, rb.c, rb.s, 0.0);
        }
        // Each of ca, sa, cb, sb is off by at most e = kApproxCosSinError: rel's cos and sin by 4e
        // (plus rounding), the shift by 2e (|dx| + |dy|); a point p of B (|p.x| + |p.y| <= the box's
        // or the samples' reach, max_abs + max_radius + the box's fit margin) by
        // 8e |p| + 2e (|dx| + |dy|). Taken 10x wider.
        const double reach = 2 * b.reach() + 1;
        set_relative(ca, sa, cb, sb,
                     10 * kApproxCosSinError * (8 * reach + 2 * (std::abs(pb.x - pa.x) + std::abs(pb.y - pa.y))));
    }

    /// The root boxes' separating-axis test (as overlap(Obb2, Obb2)) written out in A's frame: B's
    /// box rotated by rel, its half extents grown by rel_error_. The four axes' projections share
    /// cos and sin of the angle between the boxes' axes.
    bool root_boxes_overlap() const {
        const Obb2 &ba = a.root_box(), &bb = b.root_box();
        const double ux = rc_ * bb.axis.x - rs_ * bb.axis.y, uy = rs_ * bb.axis.x + rc_ * bb.axis.y;
        const double cx = rc_ * bb.center.x - rs_ * bb.center.y + sx_ - ba.center.x;
        const double cy = rs_ * bb.center.x + rc_ * bb.center.y + sy_ - ba.center.y;
        const double ax = ba.axis.x, ay = ba.axis.y, hx = bb.half.x + rel_error_, hy = bb.half.y + rel_error_;
        const double cs = std::abs(ax * ux + ay * uy), sn = std::abs(ax * uy - ay * ux);
        return !(std::abs(cx * ax + cy * ay) > ba.half.x + hx * cs + hy * sn ||
                 std::abs(cy * ax - cx * ay) > ba.half.y + hx * sn + hy * cs ||
                 std::abs(cx * ux + cy * uy) > hx + ba.half.x * cs + ba.half.y * sn ||
                 std::abs(cy * ux - cx * uy) > hy + ba.half.x * sn + ba.half.y * cs);
    }

    /// The float frame and its margin: float rounding of inputs, frame and arithmetic is below 2^-20
    /// of `scale`; the double rounding of the exact world-frame test below 2^-50 of the world
    /// coordinates; the approximate rotations' error is rel_error_. The margin bounds how far a
    /// float distance test can be from the exact one, either way.
    void set_float_frame() {
        const double scale = a.reach() + b.reach() + std::abs(sx_) + std::abs(sy_);
        const double world = std::abs(pa.x) + std::abs(pa.y) + std::abs(pb.x) + std::abs(pb.y);
        margin = float(scale * 0x1p-18 + (world + scale) * 0x1p-40 + rel_error_);
        c = float(rc_), s = float(rs_), tx = float(sx_), ty = float(sy_);
    }

    /// Bit k set when circle i + k of A and circle j + k of B may overlap, k < 4 (never clear for
    /// circles holding a colliding pair). Branch-free.
    unsigned circles4(const Circles& ca, std::int64_t i, const Circles& cb, std::int64_t j) const {
        return discs4(ca.x + i, ca.y + i, ca.r + i, cb.x + j, cb.y + j, cb.r + j);
    }
    /// Circle i of A against circle j of B, one at a time.
    bool circles_overlap(const Circles& ca, std::int64_t i, const Circles& cb, std::int64_t j) const {
        const float rr = ca.r[i] + cb.r[j] + margin;
        return distance2(ca.x[i], ca.y[i], cb.x[j], cb.y[j]) < rr * rr;
    }

    /// A candidate pair (i, j), 0 <= j < size of B: time on sample_time(), then space. The float test
    /// decides when it is clear of the margin either way (a pair inside r_a + r_b - margin collides
    /// by samples_overlap() too); only the pairs within the margin of touching need the exact
    /// world-frame test, and with it the placements' std::cos / std::sin.
    bool confirm(std::int64_t i, std::int64_t j) const {
        const double dta = a.path().dt;
        if (!times_overlap(sample_time(pa, dta, i), sample_time(pa, dta, i + 1), sample_time(pb, dta, j),
                           sample_time(pb, dta, j + 1)))
            return false;
        const float rr = a.rs()[i] + b.rs()[j];
        const float d2 = distance2(a.xs()[i], a.ys()[i], b.xs()[j], b.ys()[j]);
        const float outer = rr + margin, inner = rr - margin;
        if (!(d2 < outer * outer)) return false;
        if (!(inner > 0 && d2 < inner * inner) &&
            !samples_overlap(frame_a(), a.path().samples[std::size_t(i)], frame_b(), b.path().samples[std::size_t(j)]))
            return false;
        if (hit) *hit = {i, j};
        return true;
    }

    /// Different sample spacings, or offsets beyond aligned()'s arithmetic: the exact two-pointer walk
    /// shared with the trees' leaves.
    bool general_scan() const {
        std::uint64_t tested = 0;
        SamplePair h;
        const bool found = leaf_test(a.path(), pa, frame_a(), 0, std::int64_t(a.size()), b.path(), pb, frame_b(), 0,
                                     std::int64_t(b.size()), tested, h);
        if (found && hit) *hit = h;
        return found;
    }

private:
    const Rigid2* given_a_;
    const Rigid2* given_b_;
    double rc_, rs_, sx_, sy_;  // B's frame in A's: R_a^T R_b and R_a^T (t_b - t_a)
    double rel_error_;          // bound on the error of rel from approximate rotations, as a length (metres)

    void set_relative(double ca, double sa, double cb, double sb, double error) {
        rc_ = ca * cb + sa * sb;
        rs_ = ca * sb - sa * cb;
        const double dx = pb.x - pa.x, dy = pb.y - pa.y;
        sx_ = ca * dx + sa * dy, sy_ = -sa * dx + ca * dy;
        rel_error_ = error;
    }
    // The placements' frames as the exact test uses them (a candidate within the margin of touching
    // is rare: they are not kept).
    Rigid2 frame_a() const { return given_a_ ? *given_a_ : Rigid2::of(pa); }
    Rigid2 frame_b() const { return given_b_ ? *given_b_ : Rigid2::of(pb); }
};

}  // namespace mobb::detail
