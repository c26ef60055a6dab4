// What the film's tests share: an analytic scene (a wall seen head-on, the sky above it) and a
// comparison of films bit for bit.
#pragma once

#include "film/film.h"
#include "scene/camera_framing.h"
#include "scene/scene.h"
#include "scene/surface_part.h"

#include <gtest/gtest.h>

#include <cstring>

namespace urbis::test {

inline constexpr uint32_t kWallObject = 7;
inline constexpr SurfacePart kWallPart = SurfacePart::Facade;
inline constexpr float kWallTop = 50.0f;        ///< metres; the wall spans y 0 .. kWallTop in the plane z = 0
inline constexpr float kWallDistance = 40.0f;   ///< the camera's distance from the wall, metres
inline const Vec3f kWallAlbedo{0.6f, 0.45f, 0.3f};

/// A wall of two triangles, 400 m wide, in the plane z = 0 facing +z, under a uniform sky; with
/// `groundAndSun`, also the ground plane and a low sun, for paths that bounce and cast shadows.
inline Scene wallScene(bool groundAndSun = false) {
    TriangleMesh mesh;
    const float h = 200.0f;
    const Vec3f a{-h, 0, 0}, b{h, 0, 0}, c{h, kWallTop, 0}, d{-h, kWallTop, 0};
    const TriangleInfo info{0, kWallObject, uint32_t(kWallPart)};
    mesh.add({a, b, c}, info);
    mesh.add({a, c, d}, info);
    Material glossyGround{Vec3f{0.3f, 0.3f, 0.3f}, MaterialKind::Glossy, Vec3f{0.2f, 0.2f, 0.2f}, 40.0f};
    std::vector<GroundRecord> ground;
    if (groundAndSun) ground.push_back(GroundRecord::around(0.0f, 0.0f, 0.0f, 1));
    Scene scene = Scene::build({.mesh = mesh, .materials = {Material{kWallAlbedo}, glossyGround}, .grounds = ground});
    scene.sky = Sky::uniform(Vec3f{0.8f, 0.9f, 1.0f});
    if (groundAndSun) scene.sun = makeSun(25.0f, 160.0f, 0.5f, Vec3f{3.0f, 2.8f, 2.5f});
    return scene;
}

/// The camera kWallDistance in front of the wall at the height of its top, looking straight at it:
/// the upper half of the image is sky, the lower half wall.
inline Camera wallCamera(float aspect) {
    return makeLookAtCamera(Vec3f{0, kWallTop, kWallDistance}, Vec3f{0, kWallTop, 0}, 40.0f, aspect);
}

inline RenderSettings filmSettings(uint32_t width, uint32_t height, uint32_t spp) {
    RenderSettings s;
    s.width = width;
    s.height = height;
    s.spp = spp;
    return s;
}

/// Expects two films to hold the same bits in every array.
inline void expectSameFilmBits(const Film& a, const Film& b) {
    ASSERT_EQ(a.width, b.width);
    ASSERT_EQ(a.height, b.height);
    int array = 0;
    forEachFilmArray(
        [&](auto, bool, const auto& x, const auto& y) {
            ++array;
            ASSERT_EQ(x.size(), y.size()) << "array " << array;
            EXPECT_EQ(std::memcmp(x.data(), y.data(), x.size() * sizeof(x[0])), 0) << "array " << array;
        },
        a.arrays, b.arrays);
    EXPECT_EQ(array, 11);
}

} // namespace urbis::test
