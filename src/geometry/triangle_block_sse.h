// The watertight test of a TriangleBlock's four lanes at once in SSE2 (host, x86): the x86-64 baseline;
// compiled for AVX2 inside traceWideTrianglesAvx2, where the same operations take the VEX encoding.
#pragma once

#include "geometry/triangle_block_intersect.h"

#if URBIS_HAVE_SSE
#include <emmintrin.h>

namespace urbis {

/// TriangleBlockScalar's test on the four lanes at once: the same IEEE operations in the same order
/// per lane (intersectTriangle's, never fused), the same double fallback for lanes on an edge, and the
/// same choice among hits (the nearest, equal distances to the lower lane), so the same hit bit for bit.
struct TriangleBlockSse {
    static bool hit(const TriangleBlock& block, const WatertightRay& wr, Ray& ray, Hit& hit) {
        const float origin[3] = {wr.origin.x, wr.origin.y, wr.origin.z};
        // Vertex `v` relative to the ray origin along `axis`, the four lanes.
        auto rel = [&](int v, int axis) { return _mm_sub_ps(_mm_load_ps(block.p[v][axis]), _mm_set1_ps(origin[axis])); };
        const __m128 sx = _mm_set1_ps(wr.sx), sy = _mm_set1_ps(wr.sy), sz = _mm_set1_ps(wr.sz);
        const __m128 az = rel(0, wr.kz), bz = rel(1, wr.kz), cz = rel(2, wr.kz);
        const __m128 ax = _mm_sub_ps(rel(0, wr.kx), _mm_mul_ps(sx, az)), ay = _mm_sub_ps(rel(0, wr.ky), _mm_mul_ps(sy, az));
        const __m128 bx = _mm_sub_ps(rel(1, wr.kx), _mm_mul_ps(sx, bz)), by = _mm_sub_ps(rel(1, wr.ky), _mm_mul_ps(sy, bz));
        const __m128 cx = _mm_sub_ps(rel(2, wr.kx), _mm_mul_ps(sx, cz)), cy = _mm_sub_ps(rel(2, wr.ky), _mm_mul_ps(sy, cz));
        __m128 e0 = _mm_sub_ps(_mm_mul_ps(cx, by), _mm_mul_ps(cy, bx));
        __m128 e1 = _mm_sub_ps(_mm_mul_ps(ax, cy), _mm_mul_ps(ay, cx));
        __m128 e2 = _mm_sub_ps(_mm_mul_ps(bx, ay), _mm_mul_ps(by, ax));
        const __m128 zero = _mm_setzero_ps();
        const int onEdge = _mm_movemask_ps(
            _mm_or_ps(_mm_or_ps(_mm_cmpeq_ps(e0, zero), _mm_cmpeq_ps(e1, zero)), _mm_cmpeq_ps(e2, zero)));
        if (onEdge != 0) refineInDouble(onEdge, ax, ay, bx, by, cx, cy, e0, e1, e2);
        // Both faces: no lane whose edge functions have mixed signs.
        const __m128 negative =
            _mm_or_ps(_mm_or_ps(_mm_cmplt_ps(e0, zero), _mm_cmplt_ps(e1, zero)), _mm_cmplt_ps(e2, zero));
        const __m128 positive =
            _mm_or_ps(_mm_or_ps(_mm_cmpgt_ps(e0, zero), _mm_cmpgt_ps(e1, zero)), _mm_cmpgt_ps(e2, zero));
        const __m128 det = _mm_add_ps(_mm_add_ps(e0, e1), e2);
        const __m128 scaledT = _mm_add_ps(_mm_add_ps(_mm_mul_ps(e0, _mm_mul_ps(sz, az)), _mm_mul_ps(e1, _mm_mul_ps(sz, bz))),
                                          _mm_mul_ps(e2, _mm_mul_ps(sz, cz)));
        const __m128 invDet = _mm_div_ps(_mm_set1_ps(1.0f), det);
        const __m128 t = _mm_mul_ps(scaledT, invDet);
        const __m128 inRange = _mm_and_ps(_mm_cmpgt_ps(t, _mm_set1_ps(ray.tmin)), _mm_cmplt_ps(t, _mm_set1_ps(ray.tmax)));
        const int hits = _mm_movemask_ps(_mm_andnot_ps(_mm_and_ps(negative, positive), _mm_and_ps(_mm_cmpneq_ps(det, zero), inRange)));
        if (hits == 0) return false;
        alignas(16) float ts[kTriangleBlockWidth];
        _mm_store_ps(ts, t);
        int best = __builtin_ctz(unsigned(hits));
        for (unsigned rest = unsigned(hits) & (unsigned(hits) - 1u); rest != 0; rest &= rest - 1u) {
            const int l = __builtin_ctz(rest);
            if (ts[l] < ts[best]) best = l;
        }
        alignas(16) float inv[kTriangleBlockWidth], u[kTriangleBlockWidth], v[kTriangleBlockWidth];
        _mm_store_ps(inv, invDet);
        _mm_store_ps(u, e1);
        _mm_store_ps(v, e2);
        hit = {block.prim[best], ts[best], u[best] * inv[best], v[best] * inv[best]};
        ray.tmax = ts[best];
        return true;
    }

private:
    /// Lanes `lanes` of e0, e1, e2 again in double (edgeFunctionsInDouble), as intersectTriangle does
    /// when one of them is zero in float.
    static void refineInDouble(int lanes, __m128 ax, __m128 ay, __m128 bx, __m128 by, __m128 cx, __m128 cy, __m128& e0,
                               __m128& e1, __m128& e2) {
        alignas(16) float v[6][kTriangleBlockWidth], e[3][kTriangleBlockWidth];
        const __m128 rows[6] = {ax, ay, bx, by, cx, cy};
        for (int i = 0; i < 6; ++i) _mm_store_ps(v[i], rows[i]);
        _mm_store_ps(e[0], e0);
        _mm_store_ps(e[1], e1);
        _mm_store_ps(e[2], e2);
        for (unsigned rest = unsigned(lanes); rest != 0; rest &= rest - 1u) {
            const int l = __builtin_ctz(rest);
            edgeFunctionsInDouble(v[0][l], v[1][l], v[2][l], v[3][l], v[4][l], v[5][l], e[0][l], e[1][l], e[2][l]);
        }
        e0 = _mm_load_ps(e[0]);
        e1 = _mm_load_ps(e[1]);
        e2 = _mm_load_ps(e[2]);
    }
};

} // namespace urbis
#endif
