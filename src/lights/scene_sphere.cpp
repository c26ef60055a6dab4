#include "lights/scene_sphere.h"

#include <algorithm>

namespace urbis {

Bounds3f lightSceneBounds(const Scene& scene) {
    Bounds3f bounds;
    for (const Triangle& t : scene.triangles) bounds.extend(primBounds(t));
    for (const WallRecord& w : scene.walls) bounds.extend(primBounds(w));
    for (const LampRecord& l : scene.lamps) bounds.extend(primBounds(l));
    if (bounds.empty()) bounds = {{-1, 0, -1}, {1, 1, 1}};
    return bounds;
}

SceneSphere lightSceneSphere(const Scene& scene) {
    const Bounds3f bounds = lightSceneBounds(scene);
    return {bounds.centre(), std::max(0.5f * length(bounds.extent()), 1.0f)};
}

} // namespace urbis
