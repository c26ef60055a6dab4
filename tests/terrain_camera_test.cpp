// A geographic camera above the terrain: with aboveGround (`--camera-geo ...,50agl,...`) its altitude
// counts from the terrain under it, without it from y = 0 (sea level on a DEM).
#include "description/scene_parts.h"
#include "osm/geo_projection.h"
#include "terrain/terrain_build.h"

#include <gtest/gtest.h>

namespace urbis {
namespace {

TEST(TerrainCamera, AnAltitudeAboveGroundCountsFromTheTerrainUnderTheCamera) {
    TerrainParams params;
    params.kind = "fbm";
    params.size = 2000.0f;
    const GeoOrigin origin{true, 48.136, 10.0695};
    const TerrainField terrain = buildTerrain(params, origin, 0.0f, 0.0f, 0);
    CameraDescription camera;
    camera.geo = GeoCameraDescription{10.0725, 48.1375, 50.0f, 30.0f, -10.0f, true};
    const Vec2d local = GeoProjection(LonLat{origin.lon, origin.lat}).project(LonLat{camera.geo->lon, camera.geo->lat});
    const float ground = terrain.heightAt(float(local.x), float(-local.y));
    ASSERT_GT(ground, 1.0f) << "the fBm lifts the ground there";
    const Camera above = cameraOf(camera, 16.0f / 9.0f, origin, {}, groundOf(terrain));
    EXPECT_NEAR(above.position.x, float(local.x), 1e-3f);
    EXPECT_NEAR(above.position.z, float(-local.y), 1e-3f);
    EXPECT_NEAR(above.position.y, ground + 50.0f, 1e-3f);
    // Without aboveGround, or without a terrain, the altitude is above y = 0.
    camera.geo->aboveGround = false;
    EXPECT_NEAR(cameraOf(camera, 16.0f / 9.0f, origin, {}, groundOf(terrain)).position.y, 50.0f, 1e-4f);
    camera.geo->aboveGround = true;
    EXPECT_NEAR(cameraOf(camera, 16.0f / 9.0f, origin, {}, groundOf(TerrainField{})).position.y, 50.0f, 1e-4f);
}

} // namespace
} // namespace urbis
