// Small scenes with known lights for the light and integrator tests.
#pragma once

#include "lights/light_build.h"

namespace urbis::test {

/// A square of two triangles in the plane y = `height`, centred on the y axis, of side `side`.
inline void addSquare(TriangleMesh& mesh, float side, float height, uint32_t material) {
    const float h = 0.5f * side;
    const Vec3f a{-h, height, -h}, b{h, height, -h}, c{h, height, h}, d{-h, height, h};
    mesh.add({a, d, c}, {material, 1});
    mesh.add({a, c, b}, {material, 1});
}

/// A material that emits `radiance` and reflects nothing.
inline Material emitter(Vec3f radiance) {
    Material m{Vec3f{0, 0, 0}};
    m.emission = radiance;
    return m;
}

} // namespace urbis::test
