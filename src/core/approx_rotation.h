// Private to the core: cos and sin of two placements' angles at once, approximately, for the circle
// sweep's root test and filters (sweep_query.h), whose margins take the error in. The exact test
// always uses std::cos / std::sin (Rigid2::of).
#pragma once
#include <cmath>
#include <cstdint>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace mobb::detail {

/// Bound on the error of each value approx_cos_sin2() returns (its largest error over 10^8 angles,
/// tests/core/sweep_test.cpp, is below a tenth of it).
inline constexpr double kApproxCosSinError = 1e-6;
/// Largest |angle| (radians) approx_cos_sin2() takes: the reduction below stays exact to 1e-15.
inline constexpr double kApproxCosSinRange = 1e6;

/// cos and sin of x0 and x1 to within kApproxCosSinError each, for |x| <= kApproxCosSinRange (else
/// false, nothing written): Cody-Waite reduction by pi/2 in double (fdlibm's 33-bit pio2_1 and its
/// tail, so k * pio2_1 is exact; the reduced argument r is off by under 1e-15), then Taylor
/// polynomials on [-pi/4, pi/4] in float, sin to r^9 and cos to r^8 (truncation below 2e-9 and
/// 3e-8; float rounding of r and of the polynomials below 4e-7). The four values share one
/// polynomial evaluation in four SSE2 lanes and the quadrant is chosen by bit masks: no branch on
/// the angles. Float is enough: the error is bounded as a length in the filters' margins.
inline bool approx_cos_sin2(double x0, double x1, double& c0, double& s0, double& c1, double& s1) {
    if (!(std::abs(x0) <= kApproxCosSinRange) || !(std::abs(x1) <= kApproxCosSinRange)) return false;
    constexpr double kTwoOverPi = 0.63661977236758134308, kRound = 0x1.8p52;
    constexpr double kPio2Hi = 1.57079632673412561417e+00, kPio2Lo = 6.07710050650619224932e-11;
#if defined(__SSE2__)
    // Lanes: sin x0, sin x1, cos x0, cos x1 before the quadrant; coefficients of r^0, r^2, ... (sin's
    // multiplied by r after).
    alignas(16) static constexpr float kP[5][4] = {{1.0f, 1.0f, 1.0f, 1.0f},
                                                   {-1.0f / 6, -1.0f / 6, -0.5f, -0.5f},
                                                   {1.0f / 120, 1.0f / 120, 1.0f / 24, 1.0f / 24},
                                                   {-1.0f / 5040, -1.0f / 5040, -1.0f / 720, -1.0f / 720},
                                                   {1.0f / 362880, 1.0f / 362880, 1.0f / 40320, 1.0f / 40320}};
    alignas(16) static constexpr double kD[4][2] = {
        {kTwoOverPi, kTwoOverPi}, {kRound, kRound}, {kPio2Hi, kPio2Hi}, {kPio2Lo, kPio2Lo}};
    alignas(16) static constexpr std::int32_t kCosQuadrant[4] = {0, 0, 1, 1};
    alignas(16) static constexpr std::uint32_t kSign[4] = {0x80000000u, 0x80000000u, 0x80000000u, 0x80000000u};
    const __m128d x = _mm_set_pd(x1, x0);
    // t's low mantissa bits hold k, the nearest integer to x 2/pi (round-to-nearest mode), also for
    // negative k: t = 1.5 2^52 + k.
    const __m128d t = _mm_add_pd(_mm_mul_pd(x, _mm_load_pd(kD[0])), _mm_load_pd(kD[1]));
    const __m128d k = _mm_sub_pd(t, _mm_load_pd(kD[1]));
    const __m128d rd = _mm_sub_pd(_mm_sub_pd(x, _mm_mul_pd(k, _mm_load_pd(kD[2]))), _mm_mul_pd(k, _mm_load_pd(kD[3])));
    const __m128 r = _mm_cvtpd_ps(rd);      // r0, r1, 0, 0
    const __m128 rr = _mm_movelh_ps(r, r);  // r0, r1, r0, r1
    const __m128 r2 = _mm_mul_ps(rr, rr);
    __m128 p = _mm_add_ps(_mm_mul_ps(_mm_load_ps(kP[4]), r2), _mm_load_ps(kP[3]));
    p = _mm_add_ps(_mm_mul_ps(p, r2), _mm_load_ps(kP[2]));
    p = _mm_add_ps(_mm_mul_ps(p, r2), _mm_load_ps(kP[1]));
    p = _mm_add_ps(_mm_mul_ps(p, r2), _mm_load_ps(kP[0]));
    p = _mm_mul_ps(p, _mm_movelh_ps(r, _mm_load_ps(kP[0])));  // sin lanes times r
    // Quadrant q = k mod 4 per lane: odd q swaps cos and sin; sin is negative for q = 2, 3 (bit 1 of
    // q), cos for q = 1, 2 (bit 1 of q + 1).
    const __m128i q = _mm_shuffle_epi32(_mm_castpd_si128(t), _MM_SHUFFLE(2, 0, 2, 0));
    const __m128 swap = _mm_castsi128_ps(_mm_srai_epi32(_mm_slli_epi32(q, 31), 31));
    const __m128 other = _mm_shuffle_ps(p, p, _MM_SHUFFLE(1, 0, 3, 2));
    const __m128i bit =
        _mm_slli_epi32(_mm_add_epi32(q, _mm_load_si128(reinterpret_cast<const __m128i*>(kCosQuadrant))), 30);
    const __m128 sign = _mm_and_ps(_mm_castsi128_ps(bit), _mm_load_ps(reinterpret_cast<const float*>(kSign)));
    const __m128 v = _mm_xor_ps(_mm_or_ps(_mm_andnot_ps(swap, p), _mm_and_ps(swap, other)), sign);
    const __m128d sn = _mm_cvtps_pd(v), cs = _mm_cvtps_pd(_mm_movehl_ps(v, v));
    s0 = _mm_cvtsd_f64(sn), s1 = _mm_cvtsd_f64(_mm_unpackhi_pd(sn, sn));
    c0 = _mm_cvtsd_f64(cs), c1 = _mm_cvtsd_f64(_mm_unpackhi_pd(cs, cs));
#else
    double* c[2] = {&c0, &c1};
    double* s[2] = {&s0, &s1};
    const double x[2] = {x0, x1};
    for (int n = 0; n < 2; ++n) {
        const double k = (x[n] * kTwoOverPi + kRound) - kRound;
        const auto r = float((x[n] - k * kPio2Hi) - k * kPio2Lo), r2 = r * r;
        const float sr = r * (1 + r2 * (-1.0f / 6 + r2 * (1.0f / 120 + r2 * (-1.0f / 5040 + r2 * (1.0f / 362880)))));
        const float cr = 1 + r2 * (-0.5f + r2 * (1.0f / 24 + r2 * (-1.0f / 720 + r2 * (1.0f / 40320))));
        switch (std::int64_t(k) & 3) {
            case 0: *c[n] = cr, *s[n] = sr; break;
            case 1: *c[n] = -sr, *s[n] = cr; break;
            case 2: *c[n] = -cr, *s[n] = -sr; break;
            default: *c[n] = sr, *s[n] = -cr; break;
        }
    }
#endif
    return true;
}

}  // namespace mobb::detail
