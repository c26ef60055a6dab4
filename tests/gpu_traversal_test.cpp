// Traversal parity: a million random rays over a real city give the same triangle and distance
// on the GPU (intersectScene / occludedScene in a kernel: triangles, facade walls, ground) as on the CPU.
#include "gpu_test_support.h"

#include "citygen/city_mesher.h"
#include "citygen/city_scene.h"
#include "math/rng.h"
#include "math/sampling.h"
#include "osm/osm_import.h"

#include <tbb/parallel_for.h>

#include <cmath>
#include <filesystem>

using namespace urbis;

namespace {

/// Origins in a box 40% wider than the city and up to twice its height; directions uniform on the sphere.
std::vector<Ray> randomRays(const Bounds3f& b, uint32_t count, uint32_t seed) {
    std::vector<Ray> rays(count);
    tbb::parallel_for(uint32_t(0), count, [&](uint32_t i) {
        SampleStream rng{seed, i, 0};
        Vec3f o{b.lo.x + (1.4f * rng.draw() - 0.2f) * b.extent().x, 2.0f * rng.draw() * b.hi.y,
                b.lo.z + (1.4f * rng.draw() - 0.2f) * b.extent().z};
        float z = 2.0f * rng.draw() - 1.0f, phi = 2.0f * kPi * rng.draw(), s = std::sqrt(1.0f - z * z);
        rays[i] = Ray{o, Vec3f{s * std::cos(phi), z, s * std::sin(phi)}};
    });
    return rays;
}

void expectSameHitsOnGpuAndCpu(const std::string& osmFile, uint32_t count) {
    CityModel city = importOsm(osmFile, ImportOptions{});
    CityMesh mesh = meshCity(city);
    Scene scene = buildCityScene(mesh);
    ASSERT_GT(scene.triangles.size(), 200u);  // the village: 284 roof and plain-wall triangles, SF 100,000s
    ASSERT_GT(scene.walls.size(), 50u);
    std::vector<Ray> rays = randomRays(mesh.cityBounds, count, 4242u);

    std::unique_ptr<GpuScene> gpu = GpuScene::upload(scene);
    std::vector<SurfaceHit> gpuHits = gpu->intersect(rays);
    std::vector<uint8_t> gpuBlocked = gpu->occluded(rays);
    ASSERT_EQ(gpuHits.size(), rays.size());
    ASSERT_EQ(gpuBlocked.size(), rays.size());

    const SceneView view = scene.view();
    std::vector<SurfaceHit> cpuHits(count);
    std::vector<uint8_t> cpuBlocked(count);
    tbb::parallel_for(uint32_t(0), count, [&](uint32_t i) {
        cpuHits[i] = intersectScene(view, rays[i]);
        cpuBlocked[i] = occludedScene(view, rays[i]);
    });

    size_t hits = 0, validityDiffers = 0, primDiffers = 0, distanceDiffers = 0, occlusionDiffers = 0, bitEqual = 0;
    for (uint32_t i = 0; i < count; ++i) {
        const SurfaceHit& g = gpuHits[i];
        const SurfaceHit& c = cpuHits[i];
        occlusionDiffers += gpuBlocked[i] != cpuBlocked[i];
        if (g.valid() != c.valid()) {
            if (validityDiffers++ < 5) ADD_FAILURE() << "ray " << i << ": hit on one device only";
            continue;
        }
        if (!c.valid()) continue;
        ++hits;
        const bool samePrimitive = g.kind == c.kind && g.object == c.object && g.part == c.part && g.material == c.material;
        bitEqual += samePrimitive && g.t == c.t;
        // Two triangles (or parts) sharing the hit edge are both right at the same distance.
        if (!samePrimitive && std::fabs(g.t - c.t) > 1e-5f * c.t) {
            if (primDiffers++ < 5) ADD_FAILURE() << "ray " << i << ": object " << g.object << " vs " << c.object;
        }
        if (std::fabs(g.t - c.t) > 1e-5f * c.t) {
            if (distanceDiffers++ < 5) ADD_FAILURE() << "ray " << i << ": t " << g.t << " vs " << c.t;
        }
    }
    std::printf("%s: %u rays, %zu hits, %zu bit-identical (primitive and distance)\n",
                std::filesystem::path(osmFile).filename().c_str(), count, hits, bitEqual);
    EXPECT_EQ(validityDiffers, 0u);
    EXPECT_EQ(primDiffers, 0u);
    EXPECT_EQ(distanceDiffers, 0u);
    EXPECT_EQ(occlusionDiffers, 0u);
    EXPECT_GT(hits, count / 10);
}

} // namespace

TEST(GpuTraversal, MillionRaysOverTheBavarianVillageMatchTheCpu) {
    URBIS_SKIP_WITHOUT_GPU();
    expectSameHitsOnGpuAndCpu(test::villageFile(), 1000000);
}

TEST(GpuTraversal, MillionRaysOverDowntownSanFranciscoMatchTheCpu) {
    URBIS_SKIP_WITHOUT_GPU();
    std::string file = test::sanFranciscoFile();
    if (!std::filesystem::exists(file)) GTEST_SKIP() << "no shared data: " << file;
    expectSameHitsOnGpuAndCpu(file, 1000000);
}

TEST(GpuTraversal, EmptyBatchAndEmptySceneWork) {
    URBIS_SKIP_WITHOUT_GPU();
    Scene scene = Scene::build({.materials = {Material{}}});
    std::unique_ptr<GpuScene> gpu = GpuScene::upload(scene);
    EXPECT_TRUE(gpu->intersect({}).empty());
    std::vector<SurfaceHit> hits = gpu->intersect({Ray{Vec3f{0, 1, 0}, Vec3f{0, -1, 0}}});
    ASSERT_EQ(hits.size(), 1u);
    EXPECT_FALSE(hits[0].valid());
}
