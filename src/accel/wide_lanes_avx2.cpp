// The wide node's AVX2 lane test: only this function is compiled for AVX2 (a target attribute), so
// the rest of urbis runs on baseline x86-64 and calls it only where the CPU has AVX2 (wide_isa.h).
#include "accel/wide_bvh_traverse.h"

#if URBIS_HAVE_SSE
#include <immintrin.h>

namespace urbis {

namespace {

/// Plane row `row` of the node's eight lanes decoded along `axis`: bytes widened to floats, as decodePlane.
__attribute__((target("avx2"))) inline __m256 decodeRow(const WideBvhNode& node, int row, int axis) {
    const __m256i ints = _mm256_cvtepu8_epi32(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(node.q[row])));
    return _mm256_add_ps(_mm256_set1_ps(node.origin[axis]), _mm256_mul_ps(_mm256_cvtepi32_ps(ints), _mm256_set1_ps(node.step(axis))));
}

} // namespace

__attribute__((target("avx2"))) unsigned intersectWideLanesAvx2(const WideBvhNode& node, const BvhRay& r, float tmin,
                                                                 float tmax, float (&tEntry)[kWideBvhWidth]) {
    const __m256 scale = _mm256_set1_ps(kWideRobustScale);
    __m256 t0 = _mm256_set1_ps(tmin), t1 = _mm256_set1_ps(tmax);
    for (int axis = 0; axis < 3; ++axis) {
        const __m256 o = _mm256_set1_ps(r.origin[axis]), inv = _mm256_set1_ps(r.invDir[axis]);
        const __m256 n = _mm256_mul_ps(_mm256_sub_ps(decodeRow(node, r.nearPlane[axis], axis), o), inv);
        const __m256 f = _mm256_mul_ps(_mm256_mul_ps(_mm256_sub_ps(decodeRow(node, (r.nearPlane[axis] + 3) % 6, axis), o), inv), scale);
        // _mm256_max_ps(a, b) is a > b ? a : b, as in the scalar path.
        t0 = _mm256_max_ps(n, t0);
        t1 = _mm256_min_ps(f, t1);
    }
    _mm256_storeu_ps(tEntry, t0);
    return unsigned(_mm256_movemask_ps(_mm256_cmp_ps(t0, t1, _CMP_LE_OQ)));
}

WideIsa hostWideIsa() { return __builtin_cpu_supports("avx2") ? WideIsa::Avx2 : WideIsa::Sse; }

} // namespace urbis
#else
namespace urbis {
WideIsa hostWideIsa() { return WideIsa::Scalar; }
} // namespace urbis
#endif
