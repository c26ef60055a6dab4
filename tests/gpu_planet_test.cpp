// Image parity for whole planets (docs/planets.md): the same planet, camera and seed path traced on
// the GPU and on the CPU, from orbit (the disc, its limb and the atmosphere's march), from 10 km and
// 2 m above the ground (camera-relative coordinates at the surface), by day and at sunset; and under
// its cloud shell (media/cloud_shell.h) from orbit and from 10 km.
#include "gpu_test_support.h"

#include "media/cloud_build.h"
#include "planet/planet_build.h"

#include <cstdio>
#include <string>

using namespace urbis;

// Metric: per-pixel luminance of the linear images (mean of spp samples). The march is plain
// shading-style arithmetic (not the exact helpers: its hits are the fBm's, which the GPU evaluates
// with contracted multiply-adds and its approximate log2 and square root), so a hit's distance may
// differ by a fraction of the march's tolerance and a path may then go elsewhere; silhouette and
// coastline pixels may flip. Tolerances: the mean absolute difference under 2 % of the mean
// luminance, at most 2 % of pixels off by more than 10 % relative. Under the cloud shell the
// tracking's paths part ways between the backends as over the city (gpu_clouds_test.cpp):
// test::expectParityOfIndependentRenders.
namespace {

/// A planet seen from `altitudeKm` over 46 N, 7.5 E (heading 250, `pitch` degrees), the sun at
/// `sunElevation`, at 192 x 128 and `spp`; with `clouds` (coverage), the cloud shell around it.
struct PlanetView {
    Scene scene;
    Camera camera;
    RenderSettings settings;
    std::string label;
};
PlanetView planetView(double altitudeKm, float pitch, float sunElevation, float clouds, uint32_t spp) {
    PlanetShape shape;
    shape.seaLevel = 400.0f;
    PlanetCameraPlacement placement;
    placement.altitude = altitudeKm * 1e3;
    placement.lat = 46.0;
    placement.lon = 7.5;
    placement.pitch = pitch;
    placement.heading = 250.0f;
    PlanetView v;
    v.settings.width = 192;
    v.settings.height = 128;
    v.settings.spp = spp;
    v.settings.seed = 7;
    const PlanetRecord pl = makePlanetRecord(shape, placement, v.settings.height, 0);
    Sky sky;
    sky.model = SkyModel::Atmosphere;
    v.scene = buildPlanetScene(pl, {0.01f, 0.03f, 0.07f}, makeSun(sunElevation, 250.0f, 0.27f, {3.3f, 3.1f, 2.8f}),
                               NightSky{}, planetSky(sky, pl, 1.0f));
    if (clouds > 0.0f) {
        CloudLayer layer;
        layer.coverage = clouds;
        buildClouds(v.scene, layer);
    }
    v.camera = planetCamera(placement, float(v.settings.width) / float(v.settings.height));
    char label[128];
    std::snprintf(label, sizeof label, "planet (%.3f km up, pitch %.0f, sun %.0f, clouds %.1f)", altitudeKm, double(pitch),
                  double(sunElevation), double(clouds));
    v.label = label;
    return v;
}

void expectPlanetImagesMatch(double altitudeKm, float pitch, float sunElevation) {
    const PlanetView v = planetView(altitudeKm, pitch, sunElevation, 0.0f, 16);
    LinearImage cpu, gpu;
    const test::LuminanceParity parity = test::renderOnBoth(v.scene, v.camera, v.settings, v.label.c_str(), cpu, gpu, 0.1);
    ASSERT_GT(parity.mean, 1e-4) << "the image is black";
    test::expectParity(parity, 0.02, 0.02);
}

} // namespace

TEST(GpuPlanet, FromOrbitMatchesTheCpu) {
    URBIS_SKIP_WITHOUT_GPU();
    expectPlanetImagesMatch(12000.0, -90.0f, 40.0f);
}

TEST(GpuPlanet, FromTenKilometresMatchesTheCpu) {
    URBIS_SKIP_WITHOUT_GPU();
    expectPlanetImagesMatch(10.0, -10.0f, 40.0f);
}

TEST(GpuPlanet, TwoMetresAboveTheGroundAtSunsetMatchesTheCpu) {
    URBIS_SKIP_WITHOUT_GPU();
    expectPlanetImagesMatch(0.002, 5.0f, 3.0f);
}

TEST(GpuPlanetClouds, CloudShellFromOrbitMatchesTheCpu) {
    URBIS_SKIP_WITHOUT_GPU();
    const PlanetView v = planetView(12000.0, -90.0f, 40.0f, 0.4f, 32);
    test::expectParityOfIndependentRenders(v.scene, v.camera, v.settings, v.label.c_str());
}

TEST(GpuPlanetClouds, CloudShellFromTenKilometresMatchesTheCpu) {
    URBIS_SKIP_WITHOUT_GPU();
    const PlanetView v = planetView(10.0, -10.0f, 40.0f, 0.4f, 32);
    test::expectParityOfIndependentRenders(v.scene, v.camera, v.settings, v.label.c_str());
}
