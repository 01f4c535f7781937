// collide_sweep and collide_scan answer exactly as the brute-force reference, on random walks,
// grid-aligned (crowd-like) time offsets, mixed spacings, degenerate and far-away placements.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "approx_rotation.h"
#include "mobb/core/brute.h"
#include "mobb/core/scan.h"
#include "mobb/core/sweep.h"
#include "random_paths.h"

namespace mobb {
namespace {

Placement random_placement(std::mt19937_64& rng, double spread, double t_spread) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    return {spread * (u(rng) - 0.5), spread * (u(rng) - 0.5), 6.283185307179586 * u(rng), t_spread * (u(rng) - 0.5)};
}

void expect_real_hit(const Path& a, const Placement& pa, const Path& b, const Placement& pb, SamplePair h) {
    ASSERT_GE(h.a, 0);
    ASSERT_GE(h.b, 0);
    ASSERT_LT(std::size_t(h.a), a.size());
    ASSERT_LT(std::size_t(h.b), b.size());
    EXPECT_TRUE(times_overlap(sample_time(pa, a.dt, h.a), sample_time(pa, a.dt, h.a + 1), sample_time(pb, b.dt, h.b),
                              sample_time(pb, b.dt, h.b + 1)));
    EXPECT_TRUE(
        samples_overlap(Rigid2::of(pa), a.samples[std::size_t(h.a)], Rigid2::of(pb), b.samples[std::size_t(h.b)]));
}

TEST(FastQueryTest, AgreesWithBruteForceOnRandomWalks) {
    std::mt19937_64 rng(31);
    int positives = 0, total = 0;
    for (int clip = 0; clip < 24; ++clip) {
        const Path a = test::random_walk(rng, 1 + clip * 53);
        const Path b = test::random_walk(rng, 1300 - clip * 50, clip % 4 == 3 ? 1.0 / 30 : 1.0 / 60);
        const ClipIndex ia = ClipIndex::build(a), ib = ClipIndex::build(b);
        for (int q = 0; q < 1000; ++q) {
            const Placement pa = random_placement(rng, 2, 3), pb = random_placement(rng, 2, 3);
            const bool expected = collide_brute(a, pa, b, pb);
            SamplePair hf, hs;
            ASSERT_EQ(collide_sweep(ia, pa, ib, pb, &hf), expected) << clip << " " << q;
            ASSERT_EQ(collide_scan(ia, pa, ib, pb, &hs), expected) << clip << " " << q;
            ASSERT_EQ(collide_sweep(ib, pb, ia, pa), expected) << clip << " " << q;
            ASSERT_EQ(collide_sweep(ia, pa, Rigid2::of(pa), ib, pb, Rigid2::of(pb)), expected) << clip << " " << q;
            if (expected) {
                expect_real_hit(a, pa, b, pb, hf);
                expect_real_hit(a, pa, b, pb, hs);
            } else {
                EXPECT_EQ(hf.a, -1);
            }
            positives += expected;
            ++total;
        }
    }
    EXPECT_GT(positives, total / 5);
    EXPECT_LT(positives, total * 4 / 5);
}

// A crowd puts every clip on the global grid k*dt: time offsets are whole samples (up to rounding),
// so intervals touch end to end and one ulp decides. Also huge global times and translations.
TEST(FastQueryTest, AgreesOnGridAlignedTimesAndLargeCoordinates) {
    std::mt19937_64 rng(32);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int clip = 0; clip < 16; ++clip) {
        const double dt = clip % 2 ? 1.0 / 30 : 1.0 / 60;
        const Path a = test::random_walk(rng, 40 + clip * 30, dt), b = test::random_walk(rng, 300 - clip * 10, dt);
        const ClipIndex ia = ClipIndex::build(a), ib = ClipIndex::build(b);
        for (int q = 0; q < 2000; ++q) {
            const double base = q % 3 == 0 ? 0.0 : (q % 3 == 1 ? 3000.0 : 1e6);
            const double far = q % 5 == 0 ? 2000.0 : 0.0;
            Placement pa = random_placement(rng, 4, 0), pb = random_placement(rng, 4, 0);
            pa.x += far, pb.x += far;
            const auto ka = std::int64_t(u(rng) * 400), kb = std::int64_t(u(rng) * 400);
            pa.t0 = double(ka) * dt + (q % 7 == 0 ? base : 0.0);
            pb.t0 = double(kb) * dt + (q % 7 == 0 ? base : 0.0);
            if (q % 11 == 0) pb.t0 = std::nextafter(pb.t0, q % 2 ? 1e300 : -1e300);
            const bool expected = collide_brute(a, pa, b, pb);
            ASSERT_EQ(collide_sweep(ia, pa, ib, pb), expected) << clip << " " << q;
            ASSERT_EQ(collide_scan(ia, pa, ib, pb), expected) << clip << " " << q;
        }
    }
}

// Touching disks in space: equality is not a collision, one ulp less is.
TEST(FastQueryTest, TouchingIsNotACollision) {
    Path a, b;
    a.samples.assign(100, {0.0, 0.0, 0.5});
    b.samples.assign(100, {0.0, 0.0, 0.5});
    const ClipIndex ia = ClipIndex::build(a), ib = ClipIndex::build(b);
    for (double x : {1.0, std::nextafter(1.0, 0.0), std::nextafter(1.0, 2.0)}) {
        const Placement pa{0, 0, 0, 0}, pb{x, 0, 0, 0.3};
        EXPECT_EQ(collide_sweep(ia, pa, ib, pb), collide_brute(a, pa, b, pb)) << x;
        EXPECT_EQ(collide_scan(ia, pa, ib, pb), collide_brute(a, pa, b, pb)) << x;
    }
}

// collide_sweep's root test and filters use approximate cos/sin (within 1e-8) and take the error into
// their margins; std::cos / std::sin are evaluated only for the exact test. Placements on the edge of
// contact (B's x found by bisection on brute force to a few ulps) at angles near the quadrant
// boundaries of the reduction, up to the 1e6 rad limit of the approximation and beyond it.
TEST(FastQueryTest, ApproximateRotationsOnTheEdgeOfContact) {
    std::mt19937_64 rng(33);
    const double half_pi = 1.5707963267948966;
    std::vector<double> angles = {0.0, 1e-300, -0.0, 2.5, -3.9, 999999.9, -1e6, 1e6, 1.0000001e6, 1e12, -7e9};
    for (int k = -8; k <= 8; ++k)
        for (double e : {-1e-9, 0.0, 1e-9}) angles.push_back(k * half_pi + e);
    for (int k : {31831, 636619})  // near the limit: k pi/2 with k large
        for (double e : {-1e-7, 0.0, 1e-7}) angles.push_back(k * half_pi + e);
    int checked = 0;
    for (int clip = 0; clip < 6; ++clip) {
        const Path a = test::random_walk(rng, 20 + clip * 90, 1.0 / 30),
                   b = test::random_walk(rng, 30 + clip * 70, 1.0 / 30);
        const ClipIndex ia = ClipIndex::build(a), ib = ClipIndex::build(b);
        for (std::size_t n = 0; n < angles.size(); ++n) {
            Placement pa{0.3, -0.2, angles[n], 0.0}, pb{0.0, 0.4, angles[(n * 7 + 3) % angles.size()], 0.0};
            if (n % 3 == 1) pb.t0 = 5.0 / 30;
            // Bisect B's x between a colliding and a clear placement, then test both ends and beyond.
            double lo = pb.x - 1.0, hi = pb.x + 50.0;  // lo: whatever it is; hi: clear
            Placement p = pb;
            p.x = lo;
            if (!collide_brute(a, pa, b, p)) continue;
            for (int it = 0; it < 200 && std::nextafter(lo, hi) < hi; ++it) {
                p.x = 0.5 * (lo + hi);
                (collide_brute(a, pa, b, p) ? lo : hi) = p.x;
            }
            for (double x : {lo, hi, std::nextafter(lo, -1e300), std::nextafter(hi, 1e300), hi + 1e-9, lo - 1e-9}) {
                p.x = x;
                const bool expected = collide_brute(a, pa, b, p);
                SamplePair h;
                ASSERT_EQ(collide_sweep(ia, pa, ib, p, &h), expected) << clip << " " << angles[n] << " " << x;
                ASSERT_EQ(collide_sweep(ib, p, ia, pa), expected) << clip << " " << angles[n] << " " << x;
                ASSERT_EQ(collide_scan(ia, pa, ib, p), expected) << clip << " " << angles[n] << " " << x;
                if (expected) expect_real_hit(a, pa, b, p, h);
                ++checked;
            }
        }
    }
    EXPECT_GT(checked, 500);
}

TEST(FastQueryTest, DegeneratePaths) {
    std::mt19937_64 rng(33);
    const Path paths[] = {test::standing_still(1), test::standing_still(57), test::circle(200), test::circle(9),
                          test::random_walk(rng, 2)};
    for (const Path& a : paths)
        for (const Path& b : paths) {
            const ClipIndex ia = ClipIndex::build(a), ib = ClipIndex::build(b);
            for (int q = 0; q < 300; ++q) {
                const Placement pa = random_placement(rng, 5, 3), pb = random_placement(rng, 5, 3);
                const bool expected = collide_all_pairs(a, pa, b, pb);
                ASSERT_EQ(collide_sweep(ia, pa, ib, pb), expected) << q;
                ASSERT_EQ(collide_scan(ia, pa, ib, pb), expected) << q;
            }
        }
}

// The plan's boundaries: time overlaps of exactly kScanPairs-ish pairs (scan / sweep switch),
// overlaps of one to a few samples at either end, one-sample clips, different spacings, rotations
// at and near +-pi and beyond the polynomial range (2^19 rad), huge offsets, jumpy paths (large
// step slack: the neighbour diagonals come from a widened filter), grid-aligned and shifted times.
TEST(FastQueryTest, PlanBoundaries) {
    std::mt19937_64 rng(35);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double pi = 3.141592653589793;
    const double thetas[] = {pi,
                             -pi,
                             std::nextafter(pi, 0.0),
                             std::nextafter(-pi, 0.0),
                             0.5 * pi,
                             -0.5 * pi,
                             0.25 * pi,
                             0x1p19,
                             -0x1p19,
                             0x1p19 + 1,
                             1e12,
                             2 * pi,
                             1e-300};
    for (int clip = 0; clip < 30; ++clip) {
        const double dt = clip % 3 == 0 ? 1.0 / 30 : 1.0 / 60;
        const int na = clip % 5 == 0 ? 1 : 1 + int(u(rng) * 300), nb = clip % 7 == 0 ? 1 : 1 + int(u(rng) * 300);
        Path a = test::random_walk(rng, na, dt), b = test::random_walk(rng, nb, clip % 4 == 1 ? 1.0 / 50 : dt);
        if (clip % 6 == 2 && nb > 3) b.samples[std::size_t(nb / 2)].x += 3.0;  // a stray frame
        const ClipIndex ia = ClipIndex::build(a), ib = ClipIndex::build(b);
        for (int q = 0; q < 1500; ++q) {
            Placement pa = random_placement(rng, 1, 0), pb = random_placement(rng, 1, 0);
            if (q % 4 == 0) pa.theta = thetas[std::size_t(q / 4) % std::size(thetas)];
            if (q % 4 == 1) pb.theta = thetas[std::size_t(q / 4) % std::size(thetas)];
            // B starts so that the overlap is `overlap` samples long at A's start or end, give or take.
            const int overlap = int(u(rng) * 140);
            const double shift = q % 3 == 0 ? 0.0 : (u(rng) - 0.5) * (q % 3 == 1 ? 1e-9 : 1.0);
            pa.t0 = double(int(u(rng) * 40)) * dt;
            pb.t0 = q % 2 ? pa.t0 + double(na - overlap) * dt + shift * dt
                          : pa.t0 - double(nb - overlap) * b.dt + shift * dt;
            if (q % 13 == 0) {
                pa.x += 1e7, pb.x += 1e7;
                pa.t0 += 1e5, pb.t0 += 1e5;
            }
            const bool expected = collide_brute(a, pa, b, pb);
            SamplePair h;
            ASSERT_EQ(collide_sweep(ia, pa, ib, pb, &h), expected) << clip << " " << q;
            ASSERT_EQ(collide_sweep(ib, pb, ia, pa), expected) << clip << " " << q;
            ASSERT_EQ(collide_scan(ia, pa, ib, pb), expected) << clip << " " << q;
            if (expected) expect_real_hit(a, pa, b, pb, h);
        }
    }
}

TEST(FastQueryTest, BuildValidates) {
    EXPECT_THROW(ClipIndex::build(Path{}), std::invalid_argument);
    Path p = test::standing_still(3);
    p.samples[1].x = 2e9;
    EXPECT_THROW(ClipIndex::build(p), std::invalid_argument);
    p.samples[1].x = NAN;
    EXPECT_THROW(ClipIndex::build(p), std::invalid_argument);
}

TEST(FastQueryTest, HierarchyCirclesHoldEveryDisk) {
    std::mt19937_64 rng(34);
    const Path p = test::random_walk(rng, 777);
    const ClipIndex idx = ClipIndex::build(p);
    for (int k = 0; k < idx.levels(); ++k) {
        const std::size_t block = std::size_t(ClipIndex::kLeaf) << k;
        const Circles c = idx.level(k);
        ASSERT_EQ(c.count, (p.size() + block - 1) / block);
        for (std::size_t i = 0; i < p.size(); ++i) {
            const std::size_t b = i / block;
            const Sample& s = p.samples[i];
            EXPECT_LE(std::hypot(s.x - c.x[b], s.y - c.y[b]) + s.r, double(c.r[b]));
        }
        for (std::size_t b = c.count; b < c.count + 8; ++b) EXPECT_TRUE(std::isnan(c.x[b]) && std::isnan(c.r[b]));
    }
    EXPECT_EQ(idx.level(idx.levels() - 1).count, 1u);
}

// The sliding windows the sweep tests A's blocks against: window g of phase p holds every disk of
// samples [s g + p - 1, s g + p + s + 1); windows without samples and the padding are NaN.
TEST(FastQueryTest, WindowsHoldEveryDisk) {
    std::mt19937_64 rng(37);
    for (int n : {1, 2, 17, 33, 100, 777}) {
        const Path p = test::random_walk(rng, n);
        const ClipIndex idx = ClipIndex::build(p);
        for (int shift : {0, ClipIndex::kLeafShift, ClipIndex::kLeafShift + 1}) {
            const std::int64_t s = std::int64_t(1) << shift;
            for (std::int64_t phase = 0; phase < s; ++phase) {
                const Circles w = idx.windows(shift, int(phase));
                ASSERT_EQ(w.count, std::size_t(n / s + 3));
                for (std::int64_t g = -1; g + 1 < std::int64_t(w.count); ++g) {
                    const auto e = std::size_t(g + 1);
                    const std::int64_t first = std::max<std::int64_t>(0, s * g + phase - 1);
                    const std::int64_t end = std::min<std::int64_t>(n, s * g + phase + s + 1);
                    if (first >= end) {
                        EXPECT_TRUE(std::isnan(w.x[e]) && std::isnan(w.r[e])) << n << " " << s << " " << g;
                        continue;
                    }
                    for (std::int64_t i = first; i < end; ++i) {
                        const Sample& sm = p.samples[std::size_t(i)];
                        EXPECT_LE(std::hypot(sm.x - w.x[e], sm.y - w.y[e]) + sm.r, double(w.r[e]));
                    }
                }
                const std::size_t padding = shift == 0 ? 16 : 4;
                for (std::size_t e = w.count; e < w.count + padding; ++e) EXPECT_TRUE(std::isnan(w.x[e]));
            }
        }
    }
}

// The sweep's approximate rotations stay within their bound (the filters' margins depend on it),
// at random angles up to the range's end and next to every quadrant boundary up to 1e6 rad.
TEST(FastQueryTest, ApproximateRotationsWithinTheirBound) {
    std::mt19937_64 rng(38);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    double worst = 0;
    const auto check = [&worst](double x0, double x1) {
        double c0 = 0, s0 = 0, c1 = 0, s1 = 0;
        ASSERT_TRUE(detail::approx_cos_sin2(x0, x1, c0, s0, c1, s1)) << x0 << " " << x1;
        worst = std::max({worst, std::abs(c0 - std::cos(x0)), std::abs(s0 - std::sin(x0)), std::abs(c1 - std::cos(x1)),
                          std::abs(s1 - std::sin(x1))});
    };
    for (int i = 0; i < 200000; ++i) {
        const double scale = i % 3 == 0 ? 4.0 : (i % 3 == 1 ? 1e3 : detail::kApproxCosSinRange);
        check(u(rng) * scale, u(rng) * scale);
    }
    for (std::int64_t k = -636619; k <= 636619; k += 997)
        for (double e : {-1e-7, 0.0, 1e-7})
            check(double(k) * 1.5707963267948966 + e, double(-k) * 0.7853981633974483 - e);
    EXPECT_LT(worst, detail::kApproxCosSinError / 4);
    double c = 0, s = 0;
    EXPECT_FALSE(detail::approx_cos_sin2(1.0000001e6, 0.0, c, s, c, s));
    EXPECT_FALSE(detail::approx_cos_sin2(0.0, NAN, c, s, c, s));
}

// Long clips (many sweep chunks) at every time offset, both orders, close placements so most
// queries reach the sweep; B from shorter than one chunk to longer than A.
TEST(FastQueryTest, LongClipsAtEveryOffset) {
    std::mt19937_64 rng(36);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const Path a = test::random_walk(rng, 2600, 1.0 / 30);
    const ClipIndex ia = ClipIndex::build(a);
    int positives = 0, total = 0;
    for (int nb : {90, 511, 513, 1800, 4100}) {
        const Path b = test::random_walk(rng, nb, 1.0 / 30);
        const ClipIndex ib = ClipIndex::build(b);
        for (int q = 0; q < 400; ++q) {
            Placement pa = random_placement(rng, 3, 0), pb = random_placement(rng, 3, 0);
            const double shift = q % 2 ? 0.0 : u(rng) - 0.5;
            pb.t0 = (double(int(u(rng) * (2600 + nb))) - nb + shift) / 30;
            const bool expected = collide_brute(a, pa, b, pb);
            SamplePair h;
            ASSERT_EQ(collide_sweep(ia, pa, ib, pb, &h), expected) << nb << " " << q;
            ASSERT_EQ(collide_sweep(ib, pb, ia, pa), expected) << nb << " " << q;
            if (expected) expect_real_hit(a, pa, b, pb, h);
            positives += expected;
            ++total;
        }
    }
    EXPECT_GT(positives, total / 10);
    EXPECT_LT(positives, total * 9 / 10);
}

}  // namespace
}  // namespace mobb
