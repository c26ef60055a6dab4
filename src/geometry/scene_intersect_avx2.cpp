// The AVX2 entry of the scene's traversal: flatten inlines the traversal, the lane test
// (wide_lanes_avx2.h) and every kind's intersector into this one function compiled for AVX2 (without
// FMA, so every operation rounds as in the baseline build: the same hits bit for bit).
#include "accel/wide_lanes_avx2.h"
#include "geometry/scene_intersect.h"

namespace urbis {

#if URBIS_HAVE_SSE
__attribute__((target("avx2"), flatten)) SurfaceHit traceSceneAvx2(const SceneView& scene, const Ray& ray, bool anyHit) {
    return traceScene<false, WideLanesAvx2>(scene, ray, anyHit);
}
#endif

} // namespace urbis
