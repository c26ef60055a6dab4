// Water as meshGroundCover draws it, rendered under the default sky and sun: a thin glass pane with
// Schlick's Fresnel for n = 1.33 over a dark bed. At grazing angles it mirrors the bright horizon;
// looking straight down it reflects 2 % of the sky and shows the dark bed through its tint, so it is
// darker than the park it lies in (the bed, not the grass under it, ends the transmitted rays).
#include "cpu/cpu_renderer.h"
#include "lights/light_build.h"
#include "scene/camera_framing.h"
#include "scene/scene.h"
#include "streets/ground_cover.h"
#include "streets/street_materials.h"

#include <gtest/gtest.h>

using namespace urbis;

namespace {

Area squareArea(AreaKind kind, double half) {
    Area a;
    a.kind = kind;
    a.polygon.outer = {{-half, -half}, {half, -half}, {half, half}, {-half, half}};
    return a;
}

/// A 2 km square lake in a 4 km park, under the default sky and sun (scene_description.h's).
Scene lakeScene() {
    CityModel city;
    city.areas = {squareArea(AreaKind::Park, 2000), squareArea(AreaKind::Water, 1000)};
    city.areas[1].polygon.outer[0].x = -400;   // the south-west corner cut off: park seen there from above
    city.areas[1].polygon.outer[0].y = -400;
    StreetMesh out;
    meshGroundCover(city, {}, out);
    Scene scene = Scene::build(out.mesh, streetMaterials(), {}, {},
                               {GroundRecord::around(0, 0, 0, uint32_t(StreetMaterial::Grass))});
    scene.sun = makeSun(40.0f, 150.0f, 0.27f, Vec3f{3.3f, 3.1f, 2.8f});
    buildLights(scene);
    return scene;
}

/// Mean luminance seen by a small camera at `position` looking along heading and pitch.
double meanLuminance(const Scene& scene, Vec3f position, float heading, float pitch, float fov) {
    RenderSettings s;
    s.width = 24;
    s.height = 16;
    s.spp = 32;
    RenderCounters counters;
    const LinearImage image =
        renderCpu(scene.view(), cameraFromHeading(position, heading, pitch, fov, 1.5f), s, false, counters);
    double sum = 0;
    for (const Vec3f& p : image.pixels) sum += luminance(p) / double(image.pixels.size());
    return sum;
}

} // namespace

TEST(StreetsWater, GrazingViewsMirrorTheSkyAndSteepOnesAreDark) {
    const Scene scene = lakeScene();
    // 2 m above the water, looking 5-11 degrees down (the sun behind): 79-85 degrees from the normal.
    const double grazing = meanLuminance(scene, {0, 2, 0}, 330.0f, -8.0f, 6.0f);
    // 60 m up, straight down (within 5 degrees of the normal).
    const double steep = meanLuminance(scene, {0, 60, 0}, 0.0f, -90.0f, 10.0f);
    // The same view over the park (south-west corner, no water).
    const double park = meanLuminance(scene, {-800, 60, 800}, 0.0f, -90.0f, 10.0f);
    const double horizon = luminance(Sky{}.horizon), zenith = luminance(Sky{}.zenith);
    std::cout << "water: grazing " << grazing << ", steep " << steep << "; park " << park << "; sky horizon "
              << horizon << ", zenith " << zenith << "\n";
    EXPECT_GT(grazing, 4.0 * steep) << "Fresnel: far more of the sky is mirrored at grazing angles";
    EXPECT_GT(grazing, 0.25 * horizon);
    EXPECT_LT(steep, 0.1 * zenith) << "deep water looks dark from above";
    EXPECT_LT(steep, 0.5 * park) << "the transmitted rays must end on the dark bed, not on the park";
}
