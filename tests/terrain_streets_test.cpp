// Streets on a terrain: a road over bumpy ground follows its smooth grade, not the bumps, and the
// terrain under it is set to that grade, so that it meets the road's edges.
#include "citygen/city_on_terrain.h"
#include "citygen/city_scene.h"
#include "citygen/street_grades.h"
#include "geometry/scene_intersect.h"

#include <gtest/gtest.h>

#include <cmath>

namespace urbis {
namespace {

TEST(TerrainStreets, ARoadFollowsTheSmoothGradeOfBumpyGround) {
    // A 10 % climb along x with bumps of 1.5 m every 12.6 m (the DEM's noise, the fBm's detail).
    auto ground = [](float x) { return 20.0f + 0.1f * x + 1.5f * std::sin(x / 2.0f); };
    std::vector<float> h;
    for (int j = 0; j <= 100; ++j)
        for (int i = 0; i <= 100; ++i) h.push_back(ground(-100.0f + 2.0f * float(i)));
    TerrainField field = TerrainField::fromSamples(-100, -100, 2, 101, 101, h);
    CityModel city;
    Road road;
    road.centerline = {{-90, 0}, {90, 0}};
    road.width = 8.0f;
    road.sidewalk = Sidewalk::None;
    city.roads = {road};
    CityMesh mesh = meshCity(city);
    const std::vector<float> graded = smoothedHeights(field, kGradeRadius);
    gradeStreets(field, mesh, graded);
    placeCityOnTerrain(mesh, field);
    const Scene scene = buildCityScene(mesh, {}, {}, field);
    const SceneView view = scene.view();

    // Along the centreline and 3 m off it: the road's top (not the terrain) straight down.
    auto roadTop = [&](float x, float z) {
        const SurfaceHit hit = intersectScene(view, Ray{{x, 100.0f, z}, {0, -1, 0}});
        EXPECT_TRUE(hit.valid() && hit.part == SurfacePart::Road) << x << "," << z << ": part " << int(hit.part);
        return 100.0f - hit.t;
    };
    // Its bends: the second difference over 2 m steps, against the ground's (1.38 m at most).
    float roadBend = 0, groundBend = 0;
    for (const float z : {0.0f, 3.0f})
        for (float x = -60.0f; x <= 60.0f; x += 2.0f) {
            roadBend = std::max(roadBend, std::fabs(roadTop(x + 2, z) - 2 * roadTop(x, z) + roadTop(x - 2, z)));
            groundBend = std::max(groundBend, std::fabs(ground(x + 2) - 2 * ground(x) + ground(x - 2)));
        }
    EXPECT_GT(groundBend, 1.0f);
    EXPECT_LT(roadBend, 0.1f * groundBend);
    // It still climbs with the ground, within the bumps' amplitude.
    for (float x = -60.0f; x <= 60.0f; x += 5.0f) EXPECT_NEAR(roadTop(x, 0), 20.0f + 0.1f * x, 1.0f) << x;
    // The terrain meets its edges: 4.5 m off the centreline the ground lies within 20 cm of the road's top.
    for (float x = -60.0f; x <= 60.0f; x += 5.0f)
        for (const float z : {-4.5f, 4.5f}) EXPECT_NEAR(field.heightAt(x, z), roadTop(x, z > 0 ? 3.5f : -3.5f), 0.2f) << x;
}

} // namespace
} // namespace urbis
