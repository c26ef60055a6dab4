// Scenes for the photon integrators' tests: a street canyon (two rows of box buildings along a street
// under the sun and a uniform sky, the ground a grey plane) and a closed diffuse box around an
// emitting square.
#pragma once

#include "lights/light_build.h"
#include "scene/camera_framing.h"
#include "scene/sun.h"

namespace urbis::test {

/// A quad a, b, c, d of two triangles.
inline void addQuad(TriangleMesh& mesh, Vec3f a, Vec3f b, Vec3f c, Vec3f d, uint32_t material, uint32_t object) {
    mesh.add({a, b, c}, {material, object, 0});
    mesh.add({a, c, d}, {material, object, 0});
}

/// The four sides and the top of the box [lo, hi] (a building: object > 0); `bottom` adds the floor.
inline void addBox(TriangleMesh& mesh, Vec3f lo, Vec3f hi, uint32_t material, uint32_t object, bool bottom = false) {
    const Vec3f p[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, lo.y, hi.z}, {lo.x, lo.y, hi.z},
                        {lo.x, hi.y, lo.z}, {hi.x, hi.y, lo.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
    addQuad(mesh, p[0], p[1], p[5], p[4], material, object);
    addQuad(mesh, p[1], p[2], p[6], p[5], material, object);
    addQuad(mesh, p[2], p[3], p[7], p[6], material, object);
    addQuad(mesh, p[3], p[0], p[4], p[7], material, object);
    addQuad(mesh, p[4], p[5], p[6], p[7], material, object);
    if (bottom) addQuad(mesh, p[0], p[3], p[2], p[1], material, object);
}

/// A street canyon along z: a street 16 m wide between two rows of four terraced buildings (20 x 22 m
/// footprints, wall to wall, 18 to 30 m high), on a ground plane of side 400 m (object 0), under a sun
/// 35 degrees up across the street and a uniform sky. Materials: ground 0, walls 1 (light, so the
/// indirect light is a large share).
inline Scene streetCanyonScene() {
    TriangleMesh mesh;
    addQuad(mesh, {-200, 0, -200}, {-200, 0, 200}, {200, 0, 200}, {200, 0, -200}, 0, 0);
    uint32_t object = 1;
    for (int side = -1; side <= 1; side += 2)
        for (int k = 0; k < 4; ++k) {
            const float x0 = side < 0 ? -28.0f : 8.0f, z0 = -44.0f + 22.0f * float(k);
            const float h = 18.0f + 4.0f * float((k * 3 + (side > 0)) % 4);
            addBox(mesh, {x0, 0, z0}, {x0 + 20.0f, h, z0 + 22.0f}, 1, object++);
        }
    Scene scene = Scene::build({.mesh = mesh,
                                .materials = {Material{Vec3f{0.4f, 0.4f, 0.4f}}, Material{Vec3f{0.7f, 0.65f, 0.6f}}}});
    scene.sun = makeSun(35.0f, 100.0f, 0.27f, Vec3f{3.3f, 3.1f, 2.8f});
    scene.sky = Sky::uniform(Vec3f{0.25f, 0.3f, 0.4f});
    buildLights(scene);
    return scene;
}

/// A camera in the canyon's street at eye level, looking along it.
inline Camera streetCanyonCamera(float aspect) { return cameraFromHeading(Vec3f{0, 1.7f, -60}, 180.0f, 8.0f, 60.0f, aspect); }

} // namespace urbis::test
