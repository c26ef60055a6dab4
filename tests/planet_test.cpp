// Whole planets (docs/planets.md): the silhouette from orbit, the march against a fine-step
// reference and its Lipschitz bound, and the precision of camera-relative coordinates at the surface.
#include "geometry/planet_intersect.h"
#include "geometry/scene_intersect.h"
#include "math/constants.h"
#include "planet/planet_build.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace urbis;

namespace {

/// The default Earth-like shape (PlanetDescription's defaults).
PlanetShape earthLike() {
    PlanetShape shape;
    shape.seaLevel = 400.0f;
    return shape;
}

/// The direction of pixel (i, j) of a w x h image of `camera`, unit.
Vec3f pixelDirection(const Camera& camera, uint32_t i, uint32_t j, uint32_t w, uint32_t h) {
    return camera.generateRay((float(i) + 0.5f) / float(w), (float(j) + 0.5f) / float(h)).dir;
}

} // namespace

// From 12000 km straight down the disc's edge lies at asin(R / d) from the nadir, R between the sea's
// radius and the shell's top (0.025 degrees apart, a fifth of a pixel here): every pixel whose centre
// lies a pixel inside that band must hit the planet and every pixel a pixel outside must miss it.
TEST(Planet, SilhouetteFromOrbitIsACircleOfTheExpectedAngularRadius) {
    const PlanetShape shape = earthLike();
    PlanetCameraPlacement placement;
    placement.altitude = 1.2e7;
    const uint32_t w = 400, h = 400;
    const PlanetRecord pl = makePlanetRecord(shape, placement, h, 0);
    const Scene scene = Scene::build({.materials = planetMaterials({0.01f, 0.03f, 0.07f}), .planets = {pl}});
    const SceneView view = scene.view();
    const Camera camera = planetCamera(placement, 1.0f);
    const double d = double(pl.centreDistance);
    const double inner = std::asin((shape.radius + shape.seaLevel) / d), outer = std::asin((shape.radius + shape.amplitude) / d);
    const double pixel = 2.0 * std::atan(camera.tanHalfFovY) / double(h);
    uint32_t hits = 0, checked = 0;
    for (uint32_t j = 0; j < h; ++j)
        for (uint32_t i = 0; i < w; ++i) {
            const Vec3f dir = pixelDirection(camera, i, j, w, h);
            const double theta = std::acos(std::min(1.0, double(-dir.y)));  // from the nadir
            const bool hit = traceScene(view, Ray{{0, 0, 0}, dir}, false).valid();
            hits += hit;
            if (theta < inner - pixel) {
                ++checked;
                EXPECT_TRUE(hit) << "pixel " << i << "," << j << " inside the disc misses it";
            } else if (theta > outer + pixel) {
                ++checked;
                EXPECT_FALSE(hit) << "pixel " << i << "," << j << " outside the disc hits it";
            }
        }
    EXPECT_GT(checked, w * h * 9 / 10);
    // The disc's area in pixels against the circle's: within the band's width of a pixel around it.
    const double radiusPixels = std::tan(0.5 * (inner + outer)) / camera.tanHalfFovY * 0.5 * double(h);
    EXPECT_NEAR(double(hits), kPi * radiusPixels * radiusPixels, 2.0 * kPi * radiusPixels * 1.0);
}

// |f(a) - f(b)| <= lipschitz |a - b| for pairs of points in the shell, near the camera and far from it
// (where the level of detail fades octaves).
TEST(Planet, TerrainDistanceKeepsItsLipschitzBound) {
    const PlanetShape shape = earthLike();
    PlanetCameraPlacement placement;
    placement.altitude = 2000.0;
    placement.lat = -12.0;
    placement.lon = 31.0;
    const PlanetRecord pl = makePlanetRecord(shape, placement, 270, 0);
    uint32_t state = 12345u;
    const auto uniform = [&] { return hashToUnit(state = pcgHash(state)); };
    float worst = 0.0f;
    for (int n = 0; n < 20000; ++n) {
        const float range = std::pow(10.0f, 1.0f + 5.0f * uniform());  // 10 m to 1000 km from the camera
        const Vec3f a{(uniform() - 0.5f) * range, -2000.0f * uniform() - range * range / (2.0f * pl.radius), (uniform() - 0.5f) * range};
        const float step = std::pow(10.0f, -2.0f + 4.0f * uniform());  // 1 cm to 100 m apart
        const Vec3f dir = normalize(Vec3f{uniform() - 0.5f, uniform() - 0.5f, uniform() - 0.5f});
        const Vec3f b = a + dir * step;
        const float ratio = std::fabs(planetTerrainDistance(pl, a) - planetTerrainDistance(pl, b)) / step;
        // Float rounding of two heights (about 1e-7 of the amplitude each) over the smallest steps.
        if (step > 0.1f) worst = std::max(worst, ratio);
    }
    std::printf("lipschitz bound %.4f, largest ratio seen %.4f\n", pl.lipschitz, worst);
    EXPECT_LE(worst, pl.lipschitz);
    EXPECT_LT(pl.lipschitz, 2.0f) << "a loose bound makes the march slow";
}

// The march never passes the surface: along rays from 2 km up at grazing to steep angles, the signed
// altitude sampled every metre changes sign nowhere before the march's hit (less its tolerance), and
// nowhere at all where it reports a miss.
TEST(Planet, MarchMissesNothingAgainstAFineStepReference) {
    const PlanetShape shape = earthLike();
    PlanetCameraPlacement placement;
    placement.altitude = 300.0;
    placement.lat = 45.5;
    placement.lon = -70.0;
    const PlanetRecord pl = makePlanetRecord(shape, placement, 270, 0);
    uint32_t hits = 0, steps = 0;
    const float range = 20000.0f, reference = 1.0f;
    for (int n = 0; n < 48; ++n) {
        const float pitch = -(0.5f + 0.75f * float(n % 16)) * float(kPi) / 180.0f, heading = 0.4f * float(n);
        const Vec3f dir{std::cos(pitch) * std::sin(heading), std::sin(pitch), -std::cos(pitch) * std::cos(heading)};
        const PlanetMarch m = marchPlanetTerrain(pl, {0, 0, 0}, dir, 0.0f, range);
        steps += m.steps;
        const float end = m.hit ? m.s : range;
        float previous = planetTerrainDistance(pl, {0, 0, 0});
        ASSERT_GT(previous, 0.0f);
        for (float s = reference; s < end - planetEpsilon(pl, dir * end); s += reference) {
            const float f = planetTerrainDistance(pl, dir * s);
            ASSERT_GT(f, 0.0f) << "ray " << n << ": the reference meets the terrain at " << s << " m, the march at "
                               << (m.hit ? m.s : -1.0f);
            previous = f;
        }
        if (m.hit) {
            ++hits;
            EXPECT_LT(planetTerrainDistance(pl, dir * m.s), planetEpsilon(pl, dir * m.s));
        }
    }
    std::printf("%u of 48 rays hit within 20 km, %.1f steps each\n", hits, double(steps) / 48.0);
    EXPECT_GT(hits, 24u);
}

namespace {

/// Largest second difference (metres) of the distances to the surface (a zero of the signed
/// altitude, by bisection around the march's hit) along 200 rays 0.5 mrad apart from `origin`, pitched
/// 30 degrees down: a smooth surface gives micrometres; positions rounded to float at planetary scale
/// give centimetres to decimetres.
double surfaceRoughness(const PlanetRecord& pl, Vec3f origin) {
    double worst = 0.0, s[3] = {};
    for (int n = 0; n < 200; ++n) {
        const float pitch = -0.5236f + 0.0005f * float(n);
        const Vec3f dir{0.0f, std::sin(pitch), -std::cos(pitch)};
        float t = 0.0f;
        bool ocean = false;
        EXPECT_TRUE(intersectPlanet(pl, Ray{origin, dir}, t, ocean));
        EXPECT_FALSE(ocean);
        float lo = t - 0.05f, hi = t + 0.1f;
        for (int i = 0; i < 40; ++i) {
            const float mid = 0.5f * (lo + hi);
            (planetTerrainDistance(pl, origin + dir * mid) > 0.0f ? lo : hi) = mid;
        }
        s[0] = s[1];
        s[1] = s[2];
        s[2] = 0.5 * (double(lo) + double(hi));
        if (n >= 2) worst = std::max(worst, std::fabs(s[2] - 2.0 * s[1] + s[0]));
    }
    return worst;
}

} // namespace

// A camera 2 m above the ground sees a stable surface: the distances to it along neighbouring rays
// have second differences of millimetres, the float rounding of a height of 1.9 km (1e-7 of it per
// octave, 20 octaves, over the sine of 30 degrees), while the terrain's finest octave is 7.6 m long.
// The same planet with its frame's origin at the centre instead of the camera (altitudes as |p| - R,
// the heightfield's point from a position of 6.4e6 m), which is what absolute float coordinates
// amount to, is rough by decimetres: the test fails without camera-relative coordinates.
TEST(Planet, SurfaceTwoMetresBelowTheCameraIsSmoothInCameraRelativeCoordinates) {
    const PlanetShape shape = earthLike();
    PlanetCameraPlacement placement;
    placement.altitude = 2.0;
    placement.lat = 30.0;
    placement.lon = 0.0;
    const PlanetRecord pl = makePlanetRecord(shape, placement, 1080, 0);
    ASSERT_GT(pl.cameraAltitude - 2.0f, pl.seaLevel + 100.0f) << "the test wants land under the camera";
    const double relative = surfaceRoughness(pl, {0, 0, 0});
    // Absolute coordinates: the same record seen from the centre; rays start at the camera's point.
    PlanetRecord absolute = pl;
    absolute.centreDistance = 0.0f;
    absolute.cameraAltitude = -pl.radius;
    absolute.lodAngle = 0.0f;  // every octave: |p| is the distance from the centre here
    const double worstAbsolute = surfaceRoughness(absolute, pl.up * pl.centreDistance);
    std::printf("second differences of distances to the surface 2 m below the camera: camera-relative %.3g m, absolute %.3g m\n",
                relative, worstAbsolute);
    EXPECT_LT(relative, 5e-3);
    EXPECT_GT(worstAbsolute, 5e-2);
}
