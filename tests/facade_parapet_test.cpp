// Parapets generated on demand: each edge's share of a flat roof's parapet rides on its wall record
// (mitred where neighbouring parapets meet, beyond the wall's end at reflex corners), and rays meet
// the same roof, deck and parapet in the procedural scene as in its triangle twin.
#include "citygen/city_mesher.h"
#include "geometry/scene_intersect.h"
#include "roof_test_buildings.h"
#include "scene/scene.h"

#include <gtest/gtest.h>

#include <random>

using namespace urbis;
using namespace urbis::test;

namespace {

constexpr float kHeight = 15.0f;  // tall enough for a parapet
constexpr int kRoofRays = 100000;

CityMesh meshFlat(const Polygon& footprint, Representation walls,
                  Representation roofs = Representation::Procedural) {
    CityModel city;
    city.buildings = {roofed(footprint, RoofShape::Flat, 0.0f, kHeight, 0.0f)};
    city.buildings[0].seed = 0x9e3779b9u;
    CityMeshOptions options;
    options.geometry.walls = walls;
    options.geometry.roofs = roofs;
    return meshCity(city, options);
}

struct RoofRays {
    int differ = 0;        ///< rays that meet another surface, or at another distance
    int parapetHits = 0;   ///< rays of `x` that meet a parapet (wall material, in its top 1.3 m)
};

/// 100,000 rays down onto the roof from 3 m above it, steeply or grazing, aimed anywhere over the
/// footprint, traced through both meshes of one building.
RoofRays compareFromAbove(const CityMesh& x, const CityMesh& y, uint32_t seed) {
    const Scene a = Scene::build({.mesh = x.mesh, .materials = x.materials, .walls = x.walls});
    const Scene b = Scene::build({.mesh = y.mesh, .materials = y.materials, .walls = y.walls});
    const Bounds3f box = x.cityBounds;
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    RoofRays out;
    for (int k = 0; k < kRoofRays; ++k) {
        const Vec3f target{box.lo.x - 1 + (box.extent().x + 2) * unit(rng), kHeight - 1.5f,
                           box.lo.z - 1 + (box.extent().z + 2) * unit(rng)};
        const float azimuth = 6.2831853f * unit(rng), slope = 0.05f + 2.0f * unit(rng);
        const Vec3f dir = normalize(Vec3f{cosf(azimuth), -slope, sinf(azimuth)});
        const Ray ray{target - dir * (4.5f / -dir.y), dir};
        const SurfaceHit p = intersectScene(a.view(), ray), q = intersectScene(b.view(), ray);
        out.parapetHits += p.valid() && p.part == SurfacePart::Facade && ray.origin.y + p.t * dir.y > kHeight - 1.3f;
        if (p.valid() != q.valid() ||
            (p.valid() && (fabsf(p.t - q.t) > 1e-3f || p.material != q.material || p.part != q.part)))
            ++out.differ;
    }
    return out;
}

} // namespace

TEST(FacadeParapet, EveryEdgeOfAnLShapeCarriesItsParapet) {
    const CityMesh out = meshFlat(lShape(), Representation::Procedural);
    ASSERT_EQ(out.walls.size(), 6u);
    EXPECT_EQ(out.trianglesByKind.at("walls"), 0u) << "no parapet left as triangles";
    int reflexEnds = 0;
    for (const WallRecord& w : out.walls) {
        EXPECT_GT(w.parapetHeight, 0.79f);
        EXPECT_LT(w.parapetHeight, 1.21f);
        EXPECT_FLOAT_EQ(w.parapetThickness, 0.3f);
        // Right-angled corners: the inner face starts and ends one thickness inside a convex corner,
        // one thickness beyond the wall's end at the reflex corner (8, 8).
        for (float end : {w.parapetInner0, w.width - w.parapetInner1}) {
            EXPECT_NEAR(std::fabs(end), 0.3f, 1e-4f);
            reflexEnds += end < 0.0f;
        }
        // The top floor's rooms end below the deck.
        EXPECT_LT(w.gridV + w.gridHeight(), w.height - w.parapetHeight);
    }
    EXPECT_EQ(reflexEnds, 2);
}

TEST(FacadeParapet, RaysFromAboveMeetTheSameRoofAsTheTwin) {
    const Polygon footprints[] = {lShape(), courtyard(), regularPolygon(24, 8), regularPolygon(5, 6)};
    for (const Polygon& footprint : footprints) {
        const CityMesh procedural = meshFlat(footprint, Representation::Procedural);
        ASSERT_FALSE(procedural.walls.empty());
        const RoofRays r = compareFromAbove(procedural, meshFlat(footprint, Representation::Triangles),
                                            uint32_t(footprint.outer.size()));
        EXPECT_LE(r.differ, kRoofRays / 10000) << footprint.outer.size() << "-gon: rays that meet another surface";
        EXPECT_GT(r.parapetHits, kRoofRays / 100) << "the rays must meet the parapets";
    }
}

// --geometry walls=procedural,roofs=triangles: the parapets are stored triangles, the same surfaces.
TEST(FacadeParapet, RoofsAsTrianglesMeshTheSameParapets) {
    const CityMesh procedural = meshFlat(lShape(), Representation::Procedural);
    const CityMesh stored = meshFlat(lShape(), Representation::Procedural, Representation::Triangles);
    ASSERT_EQ(stored.walls.size(), 6u);
    for (const WallRecord& w : stored.walls) EXPECT_EQ(w.parapetHeight, 0.0f);
    EXPECT_EQ(stored.trianglesByKind.at("walls"), 6u * 4u) << "a top and an inner face per edge";
    const RoofRays r = compareFromAbove(procedural, stored, 7u);
    EXPECT_LE(r.differ, kRoofRays / 10000);
    EXPECT_GT(r.parapetHits, kRoofRays / 100);
}
