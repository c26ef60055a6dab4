// The terrain: the noise's analytic derivatives, the hierarchy's bounds, the conservative march
// against the fixed-step reference (the accuracy goals at a small size), DEM samples against GDAL's
// own values, and a building on a slope with no gap under it.
#include "base/input_error.h"
#include "citygen/city_mesher.h"
#include "citygen/city_on_terrain.h"
#include "citygen/city_scene.h"
#include "geometry/scene_intersect.h"
#include "math/value_noise.h"
#include "nature/tree_mesher.h"
#include "scene/camera.h"
#include "terrain/dem_raster.h"
#include "terrain/dual_heightmap.h"
#include "terrain/march_accuracy.h"
#include "terrain/terrain_build.h"

#include <gdal_priv.h>
#include <gdal_utils.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

using namespace urbis;

namespace {

const std::string kOsmnx = URBIS_OSMNX_DATA;

TerrainParams smallFbm() {
    TerrainParams p;
    p.kind = "fbm";
    p.size = 1200;
    p.cell = 4;
    p.fbm.wavelength = 400;
    p.fbm.amplitude = 120;
    p.fbm.offset = 60;
    return p;
}

/// Camera rays over `field` from 60 m above its ground, looking 600 m across it.
std::vector<Ray> viewRays(const TerrainField& field, uint32_t w, uint32_t h) {
    const Bounds3f box = primBounds(field.record);
    const float x = box.centre().x, z = box.lo.z + 100.0f;
    const Camera camera = makeLookAtCamera({x, field.heightAt(x, z) + 60.0f, z}, {x, field.heightAt(x, z + 600), z + 600},
                                           50.0f, float(w) / float(h));
    std::vector<Ray> rays;
    for (uint32_t j = 0; j < h; ++j)
        for (uint32_t i = 0; i < w; ++i) rays.push_back(camera.generateRay((i + 0.5f) / w, (j + 0.5f) / h));
    return rays;
}

std::vector<float> trace(TerrainField field, TerrainMarch march, const std::vector<Ray>& rays) {
    field.record.march = march;
    const Scene scene = Scene::build({.materials = terrainMaterials(), .terrain = field});
    const SceneView view = scene.view();
    std::vector<float> t;
    for (const Ray& r : rays) {
        const SurfaceHit hit = intersectScene(view, r);
        t.push_back(hit.valid() ? hit.t : -1.0f);
    }
    return t;
}

} // namespace

TEST(TerrainNoise, AnalyticDerivativesMatchFiniteDifferences) {
    FbmParams f;
    f.wavelength = 200;
    f.amplitude = 50;
    for (int k = 0; k < 200; ++k) {
        const Vec2f p{13.7f * k - 900.0f, 7.3f * k + 211.0f};
        const Vec2f q{p.x / 37.0f, p.y / 37.0f};
        const NoiseSample n = valueNoise(3, q);
        const float e = 1e-3f;
        EXPECT_NEAR(n.gradient.x, (valueNoise(3, {q.x + e, q.y}).value - valueNoise(3, {q.x - e, q.y}).value) / (2 * e), 1e-2) << k;
        EXPECT_NEAR(n.gradient.y, (valueNoise(3, {q.x, q.y + e}).value - valueNoise(3, {q.x, q.y - e}).value) / (2 * e), 1e-2) << k;
        const NoiseSample s = fbm(f, p);
        const float h = 0.05f;
        EXPECT_NEAR(s.gradient.x, (fbm(f, {p.x + h, p.y}).value - fbm(f, {p.x - h, p.y}).value) / (2 * h), 2e-2) << k;
        EXPECT_NEAR(s.gradient.y, (fbm(f, {p.x, p.y + h}).value - fbm(f, {p.x, p.y - h}).value) / (2 * h), 2e-2) << k;
        EXPECT_LE(std::fabs(fbmTerrainHeight(f, p) - f.offset), fbmAmplitudeBound(f));
    }
}

TEST(TerrainHierarchy, BoundsContainEverySampleAndTheLevelBelow) {
    const TerrainField field = buildTerrain(smallFbm(), GeoOrigin{}, 0, 0, 0);
    const TerrainRecord& r = field.record;
    ASSERT_GE(r.levels, 8u);
    const float* d = field.data.data();
    EXPECT_EQ(r.levelWidth(r.levels - 1), 1u);
    for (uint32_t j = 0; j < r.cellsZ(); ++j)
        for (uint32_t i = 0; i < r.cellsX(); ++i) {
            const float* mm = d + r.levelStart[0] + 2 * (size_t(j) * r.levelWidth(0) + i);
            for (uint32_t c = 0; c < 4; ++c) {
                const float h = d[size_t(j + (c >> 1)) * r.nx + i + (c & 1)];
                ASSERT_LE(mm[0], h);
                ASSERT_GE(mm[1], h);
            }
        }
    for (uint32_t l = 1; l < r.levels; ++l)
        for (uint32_t j = 0; j < r.levelHeight(l - 1); ++j)
            for (uint32_t i = 0; i < r.levelWidth(l - 1); ++i) {
                const float* child = d + r.levelStart[l - 1] + 2 * (size_t(j) * r.levelWidth(l - 1) + i);
                const float* parent = d + r.levelStart[l] + 2 * (size_t(j / 2) * r.levelWidth(l) + i / 2);
                ASSERT_LE(parent[0], child[0]);
                ASSERT_GE(parent[1], child[1]);
            }
}

TEST(TerrainFbm, TheDualHeightmapBlendsASecondLandscapeByItsMask) {
    TerrainParams params = smallFbm();
    params.size = 4000;
    params.cell = 20;
    params.fade = 0;
    const TerrainField single = buildTerrain(params, GeoOrigin{}, 0, 0, 0);
    params.dual.enabled = true;
    params.dual.maskWavelength = 800;
    const TerrainField dual = buildTerrain(params, GeoOrigin{}, 0, 0, 0);
    const FbmParams second = secondLandscape(params.fbm, params.dual);
    size_t first = 0, other = 0, blended = 0;
    const TerrainRecord& r = dual.record;
    for (uint32_t j = 0; j < r.nz; ++j)
        for (uint32_t i = 0; i < r.nx; ++i) {
            const Vec2f p{r.x0 + r.cell * float(i), r.z0 + r.cell * float(j)};
            const float m = dualMask(params.dual, p), h1 = single.data[size_t(j) * r.nx + i];
            const float h2 = std::max(0.0f, fbmTerrainHeight(second, p));
            const float h = dual.data[size_t(j) * r.nx + i];
            ASSERT_GE(m, 0.0f);
            ASSERT_LE(m, 1.0f);
            // Heights below 0 are raised to 0: blend the unclamped landscapes, then clamp.
            EXPECT_NEAR(h, std::max(0.0f, (1 - m) * fbmTerrainHeight(params.fbm, p) + m * fbmTerrainHeight(second, p)), 1e-3f);
            if (m == 0.0f) {
                EXPECT_EQ(h, h1);
                ++first;
            } else if (m == 1.0f) {
                EXPECT_NEAR(h, h2, 1e-3f);
                ++other;
            } else {
                ++blended;
            }
        }
    // Both kinds of land, and the seams between them, appear over 5 mask wavelengths.
    EXPECT_GT(first, r.nx * r.nz / 10);
    EXPECT_GT(other, r.nx * r.nz / 10);
    EXPECT_GT(blended, 0u);
}

TEST(TerrainMarch, HierarchyMissesNothingTheReferenceFindsAndIsExactInHeight) {
    const TerrainField field = buildTerrain(smallFbm(), GeoOrigin{}, 0, 0, 0);
    const std::vector<Ray> rays = viewRays(field, 96, 54);
    const std::vector<float> reference = trace(field, TerrainMarch::Reference, rays);
    const std::vector<float> hierarchy = trace(field, TerrainMarch::Hierarchy, rays);
    const MarchAccuracy a = marchAccuracy(field.record, field.data.data(), rays, hierarchy, reference);
    EXPECT_GT(a.hits, rays.size() / 3);
    EXPECT_EQ(a.missed, 0u);
    EXPECT_EQ(a.extra, 0u);
    // The goal: HDE under 1 cm at 1 km (the view's hits lie within 1.5 km).
    EXPECT_LT(a.maxHde, 0.01);
    EXPECT_LT(a.meanIde, 0.25) << "within the reference's step";
    // By distance: the hits within 1 km, apart, hold the goal too; the bands count every hit once.
    EXPECT_GT(a.byDistance[0].hits, 0u);
    EXPECT_LT(a.byDistance[0].maxHde, 0.01);
    size_t banded = 0;
    for (const HdeBand& band : a.byDistance) banded += band.hits;
    EXPECT_EQ(banded, a.hits);
    // The Cambridge rule at loose parameters steps over ridges: the measure must see it.
    TerrainField loose = field;
    loose.record.leiA = 20.0f, loose.record.leiC = 1.0f;
    const std::vector<float> lei = trace(loose, TerrainMarch::Lei, rays);
    EXPECT_GT(marchAccuracy(field.record, field.data.data(), rays, lei, reference).missed, 0u);
}

TEST(TerrainMarch, RaysFromBelowAndAlongTheSurfaceAreHandled) {
    // A plane sloping 1 in 10 along x: rays straight down hit it at its height, bit for bit in range.
    std::vector<float> h;
    for (int j = 0; j < 9; ++j)
        for (int i = 0; i < 17; ++i) h.push_back(0.1f * 5.0f * i);
    const TerrainField field = TerrainField::fromSamples(-40, -20, 5, 17, 9, h);
    for (float x = -39.5f; x < 40; x += 3.1f) {
        std::vector<float> t = trace(field, TerrainMarch::Hierarchy, {Ray{{x, 100, 1.3f}, {0, -1, 0}}});
        ASSERT_GE(t[0], 0.0f);
        EXPECT_NEAR(100.0f - t[0], 0.1f * (x + 40), 1e-4f) << x;
    }
    std::vector<float> below = trace(field, TerrainMarch::Hierarchy, {Ray{{0, -5, 0}, {0, 1, 0}}});
    EXPECT_NEAR(below[0], 5.0f + 4.0f, 1e-4f);
}

TEST(TerrainDem, SamplesAtPixelCentresAreGdalsOwnValues) {
    const std::string file = kOsmnx + "/elevation1.tif";
    if (!std::filesystem::exists(file)) GTEST_SKIP() << "no DEM: " << file;
    const DemRaster dem(file);
    GDALAllRegister();
    std::unique_ptr<GDALDataset> ds(GDALDataset::Open(file.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
    ASSERT_TRUE(ds);
    double gt[6];
    ASSERT_EQ(ds->GetGeoTransform(gt), CE_None);
    ASSERT_EQ(dem.width(), ds->GetRasterXSize());
    int hasNoData = 0;
    const double noData = ds->GetRasterBand(1)->GetNoDataValue(&hasNoData);
    size_t compared = 0;
    for (int r = 0; r < dem.height(); ++r)
        for (int c = 0; c < dem.width(); ++c) {
            float value;
            ASSERT_EQ(ds->GetRasterBand(1)->RasterIO(GF_Read, c, r, 1, 1, &value, 1, 1, GDT_Float32, 0, 0), CE_None);
            if (hasNoData && double(value) == noData) continue;   // a hole: filled from its neighbours
            ++compared;
            const double lon = gt[0] + (c + 0.5) * gt[1] + (r + 0.5) * gt[2], lat = gt[3] + (c + 0.5) * gt[4] + (r + 0.5) * gt[5];
            double col, row;
            dem.pixelOf(lon, lat, col, row);
            EXPECT_NEAR(dem.sample(col, row, false), value, 1e-3f) << c << "," << r;
            EXPECT_NEAR(dem.sample(col, row, true), value, 1e-3f) << c << "," << r;
        }
    EXPECT_GT(compared, size_t(dem.width() * dem.height()) * 3 / 4);   // elevation1.tif: 96 of 888 pixels are holes
}

TEST(TerrainDem, AVrtMosaicOfBothTilesCoversEachTile) {
    const std::string a = kOsmnx + "/elevation1.tif", b = kOsmnx + "/elevation2.tif";
    if (!std::filesystem::exists(a) || !std::filesystem::exists(b)) GTEST_SKIP() << "no DEM tiles";
    const std::string vrt = (std::filesystem::temp_directory_path() / "urbis_terrain_test.vrt").string();
    GDALAllRegister();
    const char* sources[] = {a.c_str(), b.c_str()};
    int error = 0;
    GDALDatasetH mosaic = GDALBuildVRT(vrt.c_str(), 2, nullptr, sources, nullptr, &error);
    ASSERT_TRUE(mosaic);
    GDALClose(mosaic);
    const DemRaster whole(vrt), second(b);
    EXPECT_GT(whole.width(), second.width());
    for (int r = 0; r < second.height(); r += 3)
        for (int c = 1; c < second.width(); c += 3) {
            double lon, lat, col, row;
            second.lonLatOf(c + 0.5, r + 0.5, lon, lat);
            whole.pixelOf(lon, lat, col, row);
            EXPECT_NEAR(whole.sample(col, row, false), second.pixel(c, r), 1e-3f);
        }
    // Reprojected onto the tangent plane at the DEM's centre, it is San Francisco's downtown: 0 to 120 m.
    TerrainParams p;
    p.dem = vrt;
    p.detail = 0;
    const TerrainField field = buildTerrain(p, GeoOrigin{}, 0, 0, 0);
    EXPECT_GT(field.record.yMax, 20.0f);
    EXPECT_LT(field.record.yMax, 150.0f);
    EXPECT_GE(field.record.yMin, 0.0f);
    std::filesystem::remove(vrt);
}

TEST(TerrainDem, AFileGdalCannotOpenIsAnInputError) {
    TerrainParams p;
    p.dem = "/nonexistent/dem.tif";
    EXPECT_THROW(buildTerrain(p, GeoOrigin{}, 0, 0, 0), InputError);
}

TEST(TerrainCity, ABuildingOnASlopeHasNoGapUnderIt) {
    // Ground rising 1 in 4 along x; a 20 m x 12 m building across it.
    std::vector<float> h;
    for (int j = 0; j < 41; ++j)
        for (int i = 0; i < 41; ++i) h.push_back(std::max(0.0f, 0.25f * (2.0f * i - 40.0f) + 20.0f));
    const TerrainField field = TerrainField::fromSamples(-40, -40, 2, 41, 41, h);
    CityModel city;
    Building b;
    b.footprint.outer = {{-10, -6}, {10, -6}, {10, 6}, {-10, 6}};
    b.height = 12.0f;
    city.buildings = {b};
    CityMeshOptions options;
    options.streets = false;
    CityMesh mesh = meshCity(city, options);
    placeCityOnTerrain(mesh, field);
    const Scene scene = buildCityScene(mesh, {}, {}, field);
    const SceneView view = scene.view();
    // Rays from outside towards the footprint's middle, at every height from below the lowest ground to the entrance.
    size_t rays = 0;
    for (float y = 14.0f; y <= 26.0f; y += 0.25f)
        for (const Vec3f from : {Vec3f{-30, 0, 0}, Vec3f{30, 0, 0}, Vec3f{0, 0, 30}, Vec3f{0, 0, -30}, Vec3f{-25, 0, 25}}) {
            if (y <= field.heightAt(from.x, from.z)) continue;   // underground: nothing to see
            Ray ray{{from.x, y, from.z}, normalize(Vec3f{-from.x, 0, -from.z})};
            const SurfaceHit hit = intersectScene(view, ray);
            ++rays;
            ASSERT_TRUE(hit.valid()) << "y " << y << " from " << from.x << "," << from.z;
            const bool wall = hit.object == 1, terrain = hit.kind == kPrimKindOf<TerrainRecord>;
            EXPECT_TRUE(wall || terrain) << "y " << y << ": kind " << hit.kind << " object " << hit.object;
            // Short of the footprint's middle: it meets the building's side (or the ground before it).
            EXPECT_LT(hit.t, length(Vec3f{from.x, 0, from.z})) << "y " << y;
        }
    EXPECT_GT(rays, 100u);
}

// A tree's twin on a slope of 1 in 2 rises as a whole by the ground under its trunk's foot, as its
// record does: every vertex by the same height, no triangle split, the trunk upright (a per-vertex
// lift, as the streets take, would shear the crown downhill).
TEST(TerrainCity, ATreeTwinOnASlopeRisesAsAWholeByItsFoot) {
    std::vector<float> h;
    for (int j = 0; j < 41; ++j)
        for (int i = 0; i < 41; ++i) h.push_back(0.5f * (2.0f * i - 40.0f) + 30.0f);
    const TerrainField field = TerrainField::fromSamples(-40, -40, 2, 41, 41, h);
    TreeRecord tree;
    tree.base = {5.0f, 0.0f, 3.0f};
    tree.object = 7;
    CityMesh mesh;
    meshTree(tree, mesh.mesh);
    const TriangleMesh flat = mesh.mesh;
    placeCityOnTerrain(mesh, field);
    ASSERT_EQ(mesh.mesh.size(), flat.size());
    const float rise = field.heightAt(5.0f, 3.0f);
    EXPECT_NEAR(rise, 32.5f, 1e-3f);
    for (size_t i = 0; i < flat.size(); ++i)
        for (const auto vertex : {&Triangle::p0, &Triangle::p1, &Triangle::p2}) {
            const Vec3f a = flat.triangles[i].*vertex, b = mesh.mesh.triangles[i].*vertex;
            EXPECT_EQ(a.x, b.x);
            EXPECT_EQ(a.z, b.z);
            EXPECT_NEAR(b.y - a.y, rise, 1e-4f) << "triangle " << i;
        }
}
