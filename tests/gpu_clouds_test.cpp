// Clouds on the GPU against the CPU: the Bavarian village under cumulus and Hillaire's atmosphere,
// seen from above (the clouds' shadows on the village) and from the street looking up (the clouds,
// lit by the sun and the sky, and the sky through their gaps).
#include "gpu_test_support.h"

#include "citygen/city_mesher.h"
#include "citygen/city_scene.h"
#include "cpu/cpu_renderer.h"
#include "lights/light_build.h"
#include "media/atmosphere_build.h"
#include "media/cloud_build.h"
#include "osm/osm_import.h"
#include "scene/camera_framing.h"

#include <cmath>

using namespace urbis;

// Metric: per-pixel luminance of the linear images, test::expectParityOfIndependentRenders (the
// tracking's paths part ways between the backends; on the H200 the mean absolute pixel difference
// was 10-12 % of the mean at 64 spp, the means within 0.05 %).
namespace {

void expectCloudImagesMatch(bool fromStreet) {
    CityModel city = importOsm(test::villageFile(), ImportOptions{});
    CityMesh mesh = meshCity(city, CityMeshOptions{});
    Scene scene = buildCityScene(mesh);
    scene.sun = makeSun(35.0f, 140.0f, 0.27f, Vec3f{3.3f, 3.1f, 2.8f});
    scene.sky.model = SkyModel::Atmosphere;
    buildAtmosphere(scene);
    CloudLayer clouds;
    clouds.coverage = 0.6f;
    buildClouds(scene, clouds);
    buildLights(scene);
    RenderSettings settings;
    settings.width = 192;
    settings.height = 128;
    settings.spp = 64;
    settings.seed = 11;
    const float aspect = float(settings.width) / float(settings.height);
    const Vec3f centre = mesh.cityBounds.centre();
    const Camera camera = fromStreet ? cameraFromHeading(Vec3f{centre.x, 2.0f, centre.z}, 140.0f, 35.0f, 70.0f, aspect)
                                     : frameCity(mesh.cityBounds, 50.0f, aspect);
    test::expectParityOfIndependentRenders(scene, camera, settings, fromStreet ? "clouds (street)" : "clouds (above)");
}

} // namespace

TEST(GpuClouds, VillageUnderCumulusFromAboveMatchesTheCpu) {
    URBIS_SKIP_WITHOUT_GPU();
    expectCloudImagesMatch(false);
}

TEST(GpuClouds, CumulusSeenFromTheStreetMatchTheCpu) {
    URBIS_SKIP_WITHOUT_GPU();
    expectCloudImagesMatch(true);
}
