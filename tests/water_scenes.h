// Scenes of water that the water tests share (CPU and GPU): a square of water in a park, meshed by
// meshGroundCover (surface, and the bed below the ground) under a given sun.
#pragma once

#include "lights/light_build.h"
#include "scene/scene.h"
#include "streets/ground_cover.h"
#include "streets/street_materials.h"

namespace urbis::test {

/// A square area of `kind`, `half` metres each side of (0, 0).
inline Area squareArea(AreaKind kind, double half) {
    Area a;
    a.kind = kind;
    a.polygon.outer = {{-half, -half}, {half, -half}, {half, half}, {-half, half}};
    return a;
}

/// `areas` meshed over a grass ground, with streetMaterials(`water`) and the sun at `elevation`,
/// `azimuth` degrees; its lights built.
inline Scene waterScene(const std::vector<Area>& areas, float elevation, float azimuth, const WaterOptions& water = {}) {
    CityModel city;
    city.areas = areas;
    StreetOptions options;
    options.water = water;
    StreetMesh out;
    meshGroundCover(city, options, out);
    Scene scene = Scene::build({.mesh = out.mesh, .materials = streetMaterials(water),
                                .grounds = {GroundRecord::around(0, 0, 0, uint32_t(StreetMaterial::Grass))}});
    scene.sun = makeSun(elevation, azimuth, 0.27f, Vec3f{3.3f, 3.1f, 2.8f});
    buildLights(scene);
    return scene;
}

} // namespace urbis::test
