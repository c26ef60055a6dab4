// Terrain parity: random rays over an fBm landscape and over San Francisco's DEM with the city on it
// hit the same kind at the same distance on the GPU as on the CPU (the material by noise may differ
// where fast math rounds a border otherwise). The hierarchy march decides
// hits with the exact operations of urbis.h, so the distances must be equal bit for bit.
#include "gpu_test_support.h"

#include "citygen/city_mesher.h"
#include "citygen/city_scene.h"
#include "citygen/city_terrain.h"
#include "math/rng.h"
#include "math/sampling.h"
#include "osm/osm_import.h"
#include "terrain/terrain_build.h"

#include <tbb/parallel_for.h>

#include <cmath>
#include <filesystem>

using namespace urbis;

namespace {

/// Origins over the terrain's box up to 300 m above its top; directions uniform on the sphere.
std::vector<Ray> raysOver(const Bounds3f& b, uint32_t count) {
    std::vector<Ray> rays(count);
    tbb::parallel_for(uint32_t(0), count, [&](uint32_t i) {
        SampleStream rng{77u, i, 0};
        const Vec3f o{b.lo.x + rng.draw() * b.extent().x, b.lo.y + rng.draw() * (b.extent().y + 300.0f),
                      b.lo.z + rng.draw() * b.extent().z};
        const float z = 2.0f * rng.draw() - 1.0f, phi = 2.0f * kPi * rng.draw(), s = std::sqrt(1.0f - z * z);
        rays[i] = Ray{o, Vec3f{s * std::cos(phi), z, s * std::sin(phi)}};
    });
    return rays;
}

void expectSameHits(const Scene& scene, const std::vector<Ray>& rays) {
    const test::HitParity parity = test::traceOnBoth(scene, rays, kPrimKindOf<TerrainRecord>, "terrain");
    EXPECT_EQ(parity.differ, 0u);
    EXPECT_EQ(parity.occlusions, 0u);
    EXPECT_GT(parity.kindHits, rays.size() / 10);
}

} // namespace

TEST(GpuTerrain, HierarchyMarchOverAnFbmLandscapeMatchesTheCpuBitForBit) {
    URBIS_SKIP_WITHOUT_GPU();
    TerrainParams p;
    p.kind = "fbm";
    p.size = 4000;
    const TerrainField field = buildTerrain(p, GeoOrigin{}, 0, 0, 0);
    const Scene scene = Scene::build({.materials = terrainMaterials(), .terrain = field});
    expectSameHits(scene, raysOver(primBounds(field.record), 1000000));
}

TEST(GpuTerrain, SanFranciscoOnItsDemMatchesTheCpu) {
    URBIS_SKIP_WITHOUT_GPU();
    const std::string osm = test::sanFranciscoFile();
    const std::string dem = test::dataDir("URBIS_OSMNX_DATA", URBIS_OSMNX_DATA) + "/elevation1.tif";
    if (!std::filesystem::exists(osm) || !std::filesystem::exists(dem)) GTEST_SKIP() << "no shared data or DEM";
    CityModel city = importOsm(osm, ImportOptions{});
    CityMesh mesh = meshCity(city);
    TerrainParams p;
    p.dem = dem;
    const TerrainField field = cityTerrainOf(p, city.origin, mesh);
    const Scene scene = buildCityScene(mesh, {}, mesh.cityBounds.centre(), field);
    expectSameHits(scene, raysOver(primBounds(field.record), 1000000));
}
