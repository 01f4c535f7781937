// Private to the core: B's frame in A's in float, widened by a rounding margin, and the disc filter over
// it, which may only err towards "candidate". Shared by the best scan's query (pair_kernel.h) and the
// circle sweep's (sweep_query.h); each sets the frame and the margin from its own error bounds.
#pragma once

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace mobb::detail {

/// A point b of B is at (c b.x - s b.y + tx, s b.x + c b.y + ty) in A's frame; `margin` (metres) widens
/// every sum of radii by the most the float arithmetic can be off. The query sets all five before the
/// first filter.
struct DiscFilter {
    float c, s, tx, ty, margin;

    /// Squared distance between A's point (x, y) and B's (bx, by) moved into A's frame, in float.
    float distance2(float x, float y, float bx, float by) const {
        const float qx = c * bx - s * by + tx, qy = s * bx + c * by + ty;
        const float dx = x - qx, dy = y - qy;
        return dx * dx + dy * dy;
    }

    /// Bit k set when disc k of A (ax, ay, ar) and disc k of B, moved into A's frame, may overlap, k < 4.
    /// Branch-free.
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
            const float rr = ar[k] + br[k] + margin;
            mask |= unsigned(distance2(ax[k], ay[k], bx[k], by[k]) < rr * rr) << k;
        }
        return mask;
#endif
    }
};

}  // namespace mobb::detail
