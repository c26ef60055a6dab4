#include "streets/street_materials.h"

#include "math/constants.h"
#include "streets/water_depth.h"

#include <cmath>

namespace urbis {

namespace {

Material diffuse(float r, float g, float b) { return Material{Vec3f{r, g, b}}; }

/// A diffuse base under a faint Phong lobe: wet-looking or polished surfaces (paint, steel, glass).
Material glossy(Vec3f albedo, float specular, float exponent) {
    return Material{albedo, MaterialKind::Glossy, Vec3f{specular, specular, specular}, exponent};
}

} // namespace

Material waterMaterial(const WaterOptions& water) {
    Material m{Vec3f{1, 1, 1}, MaterialKind::Water};
    m.ior = 1.33f;
    m.water.absorption = water.absorption;
    // The wind blows from windFrom (clockwise from north) towards the opposite bearing; world x is
    // east and z south.
    const float towards = (water.windFrom + 180.0f) * (kPi / 180.0f);
    m.water.windX = water.windSpeed * std::sin(towards);
    m.water.windZ = -water.windSpeed * std::cos(towards);
    m.water.skipBelow = waterSurfaceLevel();
    return m;
}

std::vector<Material> streetMaterials(const WaterOptions& waterOptions) {
    // Albedos of real surfaces (linear): fresh asphalt ~0.05, worn ~0.12; concrete ~0.3; grass ~0.1-0.2;
    // road paint ~0.6-0.7 (white), ~0.45 (yellow); mown grass ~0.1-0.16 in green, about 1.6 times its red
    // (greener reads as paint once tone-mapped).
    // Water: an interface of index 1.33 (2 % reflected looking down, most of the sky at grazing
    // angles) whose refraction, absorbed along its path, ends on the bed (WaterBed) below it.
    const Material water = waterMaterial(waterOptions);
    const Vec3f bed = waterOptions.bedAlbedo;
    std::vector<Material> m = {
        diffuse(0.09f, 0.09f, 0.10f),   // Asphalt
        diffuse(0.30f, 0.29f, 0.27f),   // Concrete
        diffuse(0.25f, 0.22f, 0.20f),   // PavingStones
        diffuse(0.18f, 0.17f, 0.16f),   // Sett
        diffuse(0.16f, 0.15f, 0.14f),   // Cobblestone
        diffuse(0.28f, 0.26f, 0.22f),   // Gravel
        diffuse(0.20f, 0.16f, 0.11f),   // Dirt
        diffuse(0.08f, 0.16f, 0.05f),   // Grass
        diffuse(0.22f, 0.15f, 0.09f),   // Wood
        glossy(Vec3f{0.15f, 0.15f, 0.16f}, 0.2f, 80.0f),   // Metal
        glossy(Vec3f{0.65f, 0.65f, 0.63f}, 0.05f, 20.0f),  // PaintWhite
        glossy(Vec3f{0.60f, 0.42f, 0.05f}, 0.05f, 20.0f),  // PaintYellow
        diffuse(0.32f, 0.31f, 0.29f),   // Sidewalk
        diffuse(0.40f, 0.39f, 0.37f),   // Curb
        diffuse(0.08f, 0.13f, 0.05f),   // Park
        diffuse(0.10f, 0.16f, 0.06f),   // Lawn
        diffuse(0.06f, 0.08f, 0.04f),   // ForestFloor
        diffuse(0.16f, 0.16f, 0.14f),   // ResidentialGround
        diffuse(0.20f, 0.19f, 0.18f),   // CommercialGround
        diffuse(0.22f, 0.21f, 0.19f),   // IndustrialGround
        diffuse(0.07f, 0.17f, 0.06f),   // Pitch
        diffuse(0.35f, 0.25f, 0.15f),   // Playground
        diffuse(0.45f, 0.40f, 0.30f),   // Sand
        diffuse(0.10f, 0.12f, 0.06f),   // Scrub
        diffuse(0.12f, 0.12f, 0.13f),   // Parking
        diffuse(0.09f, 0.13f, 0.06f),   // Cemetery
        diffuse(0.20f, 0.18f, 0.09f),   // Farmland
        water,                          // Water
        diffuse(0.35f, 0.34f, 0.32f),   // BridgeConcrete
        diffuse(0.40f, 0.39f, 0.37f),   // Parapet
        diffuse(0.18f, 0.17f, 0.15f),   // Ballast
        glossy(Vec3f{0.10f, 0.10f, 0.10f}, 0.5f, 200.0f),  // RailSteel
        glossy(Vec3f{0.08f, 0.09f, 0.09f}, 0.15f, 40.0f),  // LampMetal
        glossy(Vec3f{0.20f, 0.20f, 0.21f}, 0.15f, 40.0f),  // LampHousing
        diffuse(0.80f, 0.78f, 0.70f),   // LampGlass
        diffuse(bed.x, bed.y, bed.z),   // WaterBed
    };
    static_assert(uint32_t(StreetMaterial::Count) == 36, "one material per StreetMaterial");
    return m;
}

StreetMaterial materialOf(RoadSurface surface) {
    return surface == RoadSurface::Unknown ? StreetMaterial::Asphalt : StreetMaterial(uint32_t(surface));
}

} // namespace urbis
