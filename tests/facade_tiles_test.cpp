// A wall split into BVH tiles (splitWallsIntoTiles) gives exactly the whole wall's hits: on random
// rays, the closest hit over its tiles (taken as a BVH would, shrinking tmax tile by tile, in any
// order) is the whole wall's, bit for bit, and so is whether any tile is hit at all.
#include "citygen/city_mesher.h"
#include "facade_test_walls.h"
#include "cpu/cpu_renderer.h"
#include "geometry/wall_intersect.h"
#include "integrators/aov_sample.h"
#include "layout/city_layout.h"
#include "scene/camera_framing.h"
#include "scene/scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

using namespace urbis;
using namespace urbis::test;

namespace {

/// A diagonal wall of 13 slots x 11 floors (tiles of uneven sizes), with balconies and shop
/// windows, or a curtain wall.
WallRecord bigWall(WallStyle style) {
    WallRecord w;
    giveTestFacade(style, w);
    w.origin = {-812.25f, 2.0f, 1530.5f};
    w.axisU = normalize(Vec3f{0.6f, 0, 0.8f});
    w.normal = Vec3f{w.axisU.z, 0, -w.axisU.x};
    w.slots = 13;
    w.floors = 11;
    w.slotWidth = 3.1f;
    w.floorHeight = 3.3f;
    w.width = w.gridWidth() + 1.0f;
    w.height = w.gridHeight() + 0.9f;
    w.windowWidth = 1.4f;
    w.windowHeight = 1.6f;
    w.object = 5;
    w.wallIndex = 2;
    w.cellSeed = 987654;
    return w;
}

/// A random ray that a path can carry: from in front of the wall (outside its slab or within the
/// balconies' depth, some nearly parallel to the wall), from behind its slab (inside the
/// building), or from inside a room. Each starts within the wall's extent in u and v: a ray from
/// beyond its edge could pass around the edge into the wall's solid body (between the wall plane
/// and the glass), which the building's other walls and floor close in a scene; entering the
/// solid, it may be told apart by where it enters the grid's or a tile's column.
Ray randomRay(const WallRecord& w, int kind, std::mt19937& rng) {
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::normal_distribution<float> n;
    const float u = w.width * unit(rng), v = w.height * unit(rng);
    Ray ray;
    ray.dir = normalize(Vec3f{n(rng), n(rng), n(rng)});
    switch (kind) {
    case 0:
        ray.origin = w.worldFromWall(u, v, w.depthFront + 0.01f + 20 * unit(rng));
        break;
    case 1: {
        const float a = unit(rng) * 6.2831853f, tilt = (unit(rng) - 0.5f) * 2e-2f;
        ray.origin = w.worldFromWall(u, v, 0.01f + 2 * unit(rng));
        ray.dir = normalize(w.axisU * cosf(a) + Vec3f{0, sinf(a), 0} + w.normal * tilt);
        break;
    }
    case 2: {
        const float slot = float(int(unit(rng) * w.slots)), floor = float(int(unit(rng) * w.floors));
        ray.origin = w.worldFromWall(w.gridU + w.slotWidth * (slot + 0.1f + 0.8f * unit(rng)),
                                     w.gridV + w.floorHeight * (floor + 0.1f + 0.8f * unit(rng)),
                                     -w.reveal - 0.05f - (w.depthBack - w.reveal - 0.1f) * unit(rng));
        break;
    }
    case 3:
        ray.origin = w.worldFromWall(u, v, -w.depthBack - 0.01f - 10 * unit(rng));
        break;
    default:
        ray.origin = w.worldFromWall(u, v, 0.01f + w.depthFront * unit(rng));
        break;
    }
    return ray;
}

/// Whether wall point p lies inside a solid box part (a mullion, a balcony's slab or railing).
bool insideBox(const WallRecord& w, Vec3f p) {
    const float fu = (p.x - w.gridU) / w.slotWidth, fv = (p.y - w.gridV) / w.floorHeight;
    if (fu < 0 || fv < 0 || fu >= w.slots || fv >= w.floors) return false;
    CellParts parts;
    cellParts(w, uint32_t(fv), uint32_t(fu), CellSide::Both, parts);
    for (int k = 0; k < parts.count; ++k) {
        const WallPart& q = parts.parts[k];
        if (q.axis == kWallPartBox && p.x >= q.lo.x && p.x <= q.hi.x && p.y >= q.lo.y && p.y <= q.hi.y &&
            p.z >= q.lo.z && p.z <= q.hi.z)
            return true;
    }
    return false;
}

struct TileCounts {
    size_t rays = 0, hits = 0, differ = 0;
};

TileCounts compareTiles(const WallRecord& wall, WallTileSize size, size_t rays, uint32_t seed) {
    std::vector<WallRecord> tiles = splitWallsIntoTiles({wall}, size);
    std::mt19937 rng(seed);
    TileCounts out;
    for (size_t k = 0; k < rays; ++k) {
        Ray ray = randomRay(wall, int(k % 5), rng);
        while (insideBox(wall, WallRay(wall, ray).o)) ray = randomRay(wall, int(k % 5), rng);
        WallHit whole, any;
        const bool a = intersectWall<false>(wall, ray, whole);
        std::shuffle(tiles.begin(), tiles.end(), rng);
        Ray r = ray;
        WallHit best;
        bool b = false, c = false;
        for (const WallRecord& tile : tiles) {
            WallHit h;
            if (intersectWall<false>(tile, r, h)) {
                b = true;
                best = h;
                r.tmax = h.t;
            }
            c = c || intersectWall<true>(tile, ray, any);
        }
        ++out.rays;
        out.hits += a;
        if (a != b || a != c ||
            (a && (whole.t != best.t || whole.axis != best.axis || whole.material != best.material ||
                   whole.part != best.part)))
            ++out.differ;
    }
    return out;
}

} // namespace

TEST(FacadeTiles, SplitCoversEveryCellOnce) {
    const WallRecord wall = bigWall(WallStyle::Punched);
    for (WallTileSize size : {WallTileSize{4, 4}, WallTileSize{8, 8}, WallTileSize{5, 3}, WallTileSize{1, 1},
                              WallTileSize{100, 100}}) {
        std::vector<int> covered(size_t(wall.slots) * wall.floors, 0);
        const std::vector<WallRecord> tiles = splitWallsIntoTiles({wall}, size);
        for (const WallRecord& t : tiles) {
            EXPECT_LE(t.tileSlotEnd() - t.slot0, size.slots);
            EXPECT_LE(t.tileFloorEnd() - t.floor0, size.floors);
            for (int j = t.floor0; j < t.tileFloorEnd(); ++j)
                for (int i = t.slot0; i < t.tileSlotEnd(); ++i) ++covered[size_t(j) * wall.slots + size_t(i)];
        }
        EXPECT_TRUE(std::all_of(covered.begin(), covered.end(), [](int n) { return n == 1; }));
    }
    // A whole wall is its own single tile, unchanged.
    const std::vector<WallRecord> one = splitWallsIntoTiles({wall}, {100, 100});
    ASSERT_EQ(one.size(), 1u);
    EXPECT_EQ(one[0].tileSlotEnd(), int(wall.slots));
    EXPECT_EQ(one[0].tileU1(), wall.width);
}

TEST(FacadeTiles, TilesGiveTheWholeWallsHits) {
    for (WallStyle style : {WallStyle::Punched, WallStyle::Curtain})
        for (WallTileSize size : {WallTileSize{4, 4}, WallTileSize{8, 8}, WallTileSize{3, 2}, WallTileSize{1, 1}}) {
            const TileCounts c = compareTiles(bigWall(style), size, 100000, uint32_t(size.slots * 31 + size.floors));
            EXPECT_EQ(c.differ, 0u) << (style == WallStyle::Curtain ? "curtain" : "punched") << " wall, tiles " << size.slots << " x " << size.floors << ", " << c.rays << " rays";
            EXPECT_GT(c.hits, c.rays / 5) << "the rays must actually meet the wall";
        }
}

// In a city, tiles of 4 x 4 and 2 x 3 cells show the same object and part at every pixel as whole
// walls (ID AOV, aerial and street views).
TEST(FacadeTiles, TiledCityShowsTheSameIds) {
    LayoutParams params;
    params.buildings = 150;
    params.seed = 5;
    const CityModel city = generateCity(params);
    const CityMesh mesh = meshCity(city, CityMeshOptions{});
    RenderSettings settings;
    settings.width = 240;
    settings.height = 160;
    settings.spp = 1;
    const float aspect = float(settings.width) / float(settings.height);
    const Vec3f c = mesh.cityBounds.centre(), e = mesh.cityBounds.extent();
    const Camera cameras[2] = {frameCity(mesh.cityBounds, 40.0f, aspect),
                               makeLookAtCamera(Vec3f{c.x - 0.2f * e.x, 12.0f, c.z + 0.25f * e.z},
                                                Vec3f{c.x, 8.0f, c.z}, 50.0f, aspect)};
    const Scene whole = Scene::build({.mesh = mesh.mesh, .materials = mesh.materials, .walls = mesh.walls});
    for (WallTileSize size : {WallTileSize{4, 4}, WallTileSize{2, 3}}) {
        const Scene tiled = Scene::build({.mesh = mesh.mesh, .materials = mesh.materials, .walls = mesh.walls,
                                          .tileSize = size});
        EXPECT_GT(tiled.walls.size(), whole.walls.size());
        for (const Camera& camera : cameras) {
            const std::vector<uint32_t> a = renderIdsCpu(whole.view(), camera, settings);
            const std::vector<uint32_t> b = renderIdsCpu(tiled.view(), camera, settings);
            size_t differ = 0;
            for (size_t i = 0; i < a.size(); ++i) differ += a[i] != b[i];
            EXPECT_EQ(differ, 0u) << "tiles " << size.slots << " x " << size.floors;
        }
    }
}
