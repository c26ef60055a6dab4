// The two representations of the facades render the same picture: the same object and part at
// >= 99.9 % of pixels (ID AOV) and the same image within a stated tolerance, on a real village and
// on a generated city.
#include "citygen/city_mesher.h"
#include "citygen/city_scene.h"
#include "cpu/cpu_renderer.h"
#include "integrators/aov_sample.h"
#include "layout/city_layout.h"
#include "osm/osm_import.h"
#include "scene/camera_framing.h"
#include "scene/scene.h"

#include <gtest/gtest.h>

using namespace urbis;

namespace {

Scene sceneOf(const CityModel& city, Representation walls, Bounds3f& bounds) {
    CityMeshOptions options;
    options.geometry.walls = walls;
    CityMesh mesh = meshCity(city, options);
    bounds = mesh.cityBounds;
    Scene scene = buildCityScene(mesh);
    scene.sun = makeSun(35.0f, 200.0f, 0.27f, Vec3f{3.3f, 3.1f, 2.8f});
    return scene;
}

struct TwinComparison {
    double sameId = 0;              ///< fraction of pixels with the same ID
    double facadePixels = 0;        ///< fraction of pixels that see a facade part other than the wall plane
    double meanRelativeError = 0;   ///< mean |a - b| over mean radiance, luminance
};

TwinComparison compareTwins(const CityModel& city, bool streetLevel) {
    Bounds3f bounds;
    Scene procedural = sceneOf(city, Representation::Procedural, bounds);
    Scene triangles = sceneOf(city, Representation::Triangles, bounds);
    EXPECT_FALSE(procedural.walls.empty());
    EXPECT_TRUE(triangles.walls.empty());
    EXPECT_GT(triangles.triangles.size(), 10 * procedural.triangles.size());
    RenderSettings settings;
    settings.width = 320;
    settings.height = 240;
    settings.spp = 4;
    const float aspect = float(settings.width) / float(settings.height);
    Camera camera = frameCity(bounds, 40.0f, aspect);
    if (streetLevel) {
        const Vec3f c = bounds.centre(), e = bounds.extent();
        camera = makeLookAtCamera(Vec3f{c.x - 0.2f * e.x, 12.0f, c.z + 0.25f * e.z}, Vec3f{c.x, 8.0f, c.z}, 50.0f, aspect);
    }
    const std::vector<uint32_t> a = renderIdsCpu(procedural.view(), camera, settings);
    const std::vector<uint32_t> b = renderIdsCpu(triangles.view(), camera, settings);
    TwinComparison out;
    size_t same = 0, facade = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        same += a[i] == b[i];
        const uint32_t part = a[i] & ((1u << kSurfacePartBits) - 1u);
        facade += a[i] != kSkyId && part > uint32_t(SurfacePart::Facade);
    }
    out.sameId = double(same) / double(a.size());
    out.facadePixels = double(facade) / double(a.size());
    RenderCounters counters;
    settings.width = 160;
    settings.height = 120;
    const LinearImage x = renderCpu(procedural.view(), camera, settings, false, counters);
    const LinearImage y = renderCpu(triangles.view(), camera, settings, false, counters);
    double diff = 0, sum = 0;
    for (size_t i = 0; i < x.pixels.size(); ++i) {
        diff += fabs(luminance(x.pixels[i]) - luminance(y.pixels[i]));
        sum += luminance(y.pixels[i]);
    }
    out.meanRelativeError = diff / sum;
    return out;
}

/// Stated tolerance of the image comparison: the same sample streams meet the same surfaces, so
/// only paths that graze a part's edge differ.
constexpr double kImageTolerance = 0.01;

void expectSame(const CityModel& city) {
    for (bool street : {false, true}) {
        const TwinComparison c = compareTwins(city, street);
        const char* view = street ? "street view" : "aerial view";
        EXPECT_GE(c.sameId, 0.999) << view;
        // The aerial view frames the whole city (frameCity), where windows cover about 1 % of it.
        EXPECT_GT(c.facadePixels, street ? 0.01 : 0.005) << view << ": the view must show windows";
        EXPECT_LT(c.meanRelativeError, kImageTolerance) << view;
    }
}

} // namespace

TEST(FacadeTwin, BavarianVillageRendersTheSame) {
    CityModel city = importOsm(URBIS_OSMNX_DATA "/planet_10.068,48.135_10.071,48.137.osm", ImportOptions{});
    ASSERT_GT(city.buildings.size(), 10u);
    expectSame(city);
}

TEST(FacadeTwin, GeneratedCityRendersTheSame) {
    LayoutParams params;
    params.buildings = 150;
    params.seed = 3;
    expectSame(generateCity(params));
}

// The twin is estimated before it is built: a budget too small for it is one clear error.
TEST(FacadeTwin, TwinThatDoesNotFitIsRefusedBeforeBuilding) {
    LayoutParams params;
    params.buildings = 50;
    CityModel city = generateCity(params);
    CityMeshOptions options;
    options.geometry.walls = Representation::Triangles;
    options.memoryLimit = 1 << 20;
    try {
        meshCity(city, options);
        FAIL() << "expected an InputError";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("triangle twin"), std::string::npos) << e.what();
    }
}
