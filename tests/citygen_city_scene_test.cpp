// The generated city's scene at scale: streamed citygen and the parallel Scene::build give the same
// scene, byte for byte, on any thread count, and jittered building colours share materials.
#include "citygen/city_mesher.h"
#include "citygen/city_scene.h"
#include "layout/city_layout.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cstring>

using namespace urbis;

namespace {

Scene citySceneOn(const CityModel& city, int threads, WallTileSize tiles) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    const CityMesh mesh = meshCity(city);
    return buildCityScene(mesh, tiles, mesh.cityBounds.centre());
}

template <typename T>
void expectSameBytes(const std::vector<T>& a, const std::vector<T>& b, const char* what) {
    ASSERT_EQ(a.size(), b.size()) << what;
    EXPECT_EQ(0, std::memcmp(a.data(), b.data(), a.size() * sizeof(T))) << what;
}

} // namespace

TEST(CityScene, SameSceneForAnyThreadCount) {
    // Enough buildings for many meshing chunks and for the BVH's parallel subtrees and binning.
    LayoutParams params;
    params.buildings = 3000;
    const CityModel city = generateCity(params);
    for (WallTileSize tiles : {WallTileSize{}, WallTileSize{4, 4}}) {
        const Scene one = citySceneOn(city, 1, tiles);
        ASSERT_GT(one.walls.size(), 3000u);
        ASSERT_GT(one.triangles.size(), 30000u);
        for (int threads : {2, 4}) {
            const Scene many = citySceneOn(city, threads, tiles);
            expectSameBytes(one.nodes, many.nodes, "nodes");
            expectSameBytes(one.triangles, many.triangles, "triangles");
            expectSameBytes(one.triangleInfo, many.triangleInfo, "triangle info");
            expectSameBytes(one.walls, many.walls, "walls");
            expectSameBytes(one.lamps, many.lamps, "lamps");
            expectSameBytes(one.trees, many.trees, "trees");
            expectSameBytes(one.materials, many.materials, "materials");
        }
    }
}

TEST(CityScene, JitteredColoursShareMaterials) {
    // Each building's colour is a palette's times its own jitter: kept to 1/1024 steps, the buildings
    // share materials (some 2,100 here, at most some 5,000 however many buildings) rather than take one,
    // or two with a pitched roof, each (about 3,900 here).
    LayoutParams params;
    params.buildings = 3000;
    const CityMesh mesh = meshCity(generateCity(params));
    EXPECT_LT(mesh.materials.size(), params.buildings);
}
