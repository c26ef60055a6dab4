// The wide node's lane test in AVX2 (host, x86 only). Only code compiled for AVX2 may inline it:
// an entry function with __attribute__((target("avx2"), flatten)) that a dispatch on hostWideIsa()
// calls (wide_triangle_scene_avx2.cpp), so that urbis runs on baseline x86-64 and the traversal
// around the test is compiled for AVX2 too.
#pragma once

#include "accel/wide_bvh_traverse.h"

#if URBIS_HAVE_SSE
#include <immintrin.h>

namespace urbis {

/// WideLanesScalar's test in AVX2: the eight lanes at once.
struct WideLanesAvx2 {
    /// Plane row `row` of the node's eight lanes decoded along `axis`: bytes widened to floats, as decodePlane.
    __attribute__((target("avx2"))) static __m256 decodeRow(const WideBvhNode& node, int row, int axis) {
        const __m256i ints = _mm256_cvtepu8_epi32(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(node.q[row])));
        return _mm256_add_ps(_mm256_set1_ps(node.origin[axis]),
                             _mm256_mul_ps(_mm256_cvtepi32_ps(ints), _mm256_set1_ps(node.step(axis))));
    }

    __attribute__((target("avx2"))) static unsigned test(const WideBvhNode& node, const BvhRay& r, float tmin, float tmax,
                                                         float (&tEntry)[kWideBvhWidth]) {
        const __m256 scale = _mm256_set1_ps(kWideRobustScale);
        __m256 t0 = _mm256_set1_ps(tmin), t1 = _mm256_set1_ps(tmax);
        for (int axis = 0; axis < 3; ++axis) {
            const __m256 o = _mm256_set1_ps(r.origin[axis]), inv = _mm256_set1_ps(r.invDir[axis]);
            const __m256 n = _mm256_mul_ps(_mm256_sub_ps(decodeRow(node, r.nearPlane[axis], axis), o), inv);
            const __m256 f =
                _mm256_mul_ps(_mm256_mul_ps(_mm256_sub_ps(decodeRow(node, (r.nearPlane[axis] + 3) % 6, axis), o), inv), scale);
            // _mm256_max_ps(a, b) is a > b ? a : b, as in the scalar path.
            t0 = _mm256_max_ps(n, t0);
            t1 = _mm256_min_ps(f, t1);
        }
        _mm256_storeu_ps(tEntry, t0);
        return unsigned(_mm256_movemask_ps(_mm256_cmp_ps(t0, t1, _CMP_LE_OQ)));
    }
};

} // namespace urbis
#endif
