// Small scenes with known lights for the light and integrator tests.
#pragma once

#include "lights/light_build.h"

#include <random>

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

/// The many-lights test bed: a grey plane of side `side` (y = 0) under `count` small emitting squares
/// (side 0.5 to 1.5 m, 3 to 8 m up, facing down and up) at places drawn from `seed`, of eight
/// emissions from 1 to 128 (a few bright among many dim, as lamps and windows are), a black sky and
/// no sun: a night with many lights.
inline Scene manyEmitterScene(uint32_t count, float side, uint32_t seed = 7) {
    TriangleMesh mesh;
    addSquare(mesh, side, 0.0f, 0);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (uint32_t i = 0; i < count; ++i) {
        const float x = (unit(rng) - 0.5f) * side, z = (unit(rng) - 0.5f) * side;
        const float y = 3.0f + 5.0f * unit(rng), h = 0.25f + 0.5f * unit(rng);
        const uint32_t material = 1 + uint32_t(unit(rng) * unit(rng) * 8.0f) % 8;
        const Vec3f a{x - h, y, z - h}, b{x + h, y, z - h}, c{x + h, y, z + h}, d{x - h, y, z + h};
        mesh.add({a, d, c}, {material, 1});
        mesh.add({a, c, b}, {material, 1});
    }
    std::vector<Material> materials{Material{Vec3f{0.5f, 0.5f, 0.5f}}};
    for (int k = 0; k < 8; ++k) {
        const float l = float(1 << k);  // material 1 + k, drawn less often the larger k
        materials.push_back(emitter(Vec3f{l, 0.8f * l, 0.6f * l}));
    }
    Scene scene = Scene::build({.mesh = mesh, .materials = materials});
    scene.sky = Sky::uniform(Vec3f{0, 0, 0});
    return scene;
}

} // namespace urbis::test
