#include "citygen/city_terrain.h"

#include "citygen/city_on_terrain.h"
#include "citygen/street_grades.h"
#include "terrain/terrain_build.h"

namespace urbis {

TerrainField cityTerrainOf(const TerrainParams& params, const GeoOrigin& origin, CityMesh& mesh, const WaterOptions& water) {
    if (!params.enabled()) return {};
    const Vec3f centre = mesh.cityBounds.empty() ? Vec3f{} : mesh.cityBounds.centre();
    TerrainField terrain = buildTerrain(params, origin, centre.x, centre.z, uint32_t(mesh.materials.size()));
    std::vector<Material> materials = terrainMaterials();
    // Real elevation under a city is the city's ground where nothing covers it, not a meadow.
    if (!params.hasFbm() && mesh.groundMaterial < mesh.materials.size())
        materials[uint32_t(TerrainMaterial::Grass)] = mesh.materials[mesh.groundMaterial];
    for (const Material& m : materials) mesh.materials.push_back(m);
    // Each water body at its level over the terrain, its bed: no flat layer under the surface to pass;
    // the streets on the smooth grade of the natural ground with the rivers' banks (not their beds).
    const WaterLevels levels = waterLevelsOn(mesh, terrain);
    carveRiverBanks(terrain, mesh, levels, water);
    const std::vector<float> graded = smoothedHeights(terrain, kGradeRadius);
    carveWaterBeds(terrain, mesh, levels, water);
    gradeStreets(terrain, mesh, graded);
    for (Material& m : mesh.materials)
        if (m.kind == MaterialKind::Water) m.water.skipBelow = 0;
    placeCityOnTerrain(mesh, terrain, levels);
    return terrain;
}

} // namespace urbis
