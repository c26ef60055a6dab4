// The AVX2 entry of the wide triangle traversal: flatten inlines the traversal and the block test
// into this one function compiled for AVX2, so the lane test (wide_lanes_avx2.h) inlines too.
#include "accel/wide_lanes_avx2.h"
#include "geometry/wide_triangle_scene.h"

namespace urbis {

#if URBIS_HAVE_SSE
__attribute__((target("avx2"), flatten)) Hit traceWideTrianglesAvx2(const WideTriangleSceneView& view, Ray ray,
                                                                   bool anyHit) {
    return traceWideTriangles<WideLanesAvx2, TriangleBlockSse>(view, ray, anyHit);
}
#endif

} // namespace urbis
