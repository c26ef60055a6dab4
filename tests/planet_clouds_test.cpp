// A planet's cloud shell (docs/planets.md § Cloud shell): the tracking through a homogeneous shell
// against Beer-Lambert along the chords of its spheres, and the clouds fixed to the planet as the
// camera moves.
#include "media/cloud_build.h"
#include "media/cloud_tracking.h"
#include "math/constants.h"
#include "planet/planet_build.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace urbis;

namespace {

/// A planet scene around a camera `altitude` metres above the ground at (lat, lon), with the cloud `layer`.
Scene planetWithClouds(const PlanetShape& shape, double altitude, const CloudLayer& layer, double lat = 20.0,
                       double lon = 10.0) {
    PlanetCameraPlacement placement;
    placement.altitude = altitude;
    placement.lat = lat;
    placement.lon = lon;
    const PlanetRecord pl = makePlanetRecord(shape, placement, 270, 0);
    Scene scene = Scene::build({.materials = planetMaterials({0.01f, 0.03f, 0.07f}), .planets = {pl}});
    buildClouds(scene, layer);
    return scene;
}

/// A homogeneous shell (a Uniform layer) of extinction `sigma` per metre from 1500 m over 2500 m above the sea.
CloudLayer uniformShell(float sigma) {
    CloudLayer layer;
    layer.type = CloudType::Uniform;
    layer.coverage = 1.0f;
    layer.density = sigma;
    return layer;
}

/// Length (metres) of the ray from radius r0 at `cosZenith` (to the local zenith) up to radius r, outwards.
double outwardChord(double r0, double cosZenith, double r) {
    return std::sqrt(r * r - r0 * r0 * (1.0 - cosZenith * cosZenith)) - r0 * cosZenith;
}

/// Mean and standard error of the ratio-tracked transmittance of `ray` over `n` walks, and the share
/// of `n` delta-tracked flights that collide.
struct Estimates {
    double transmittance, error, collided;
};
Estimates track(const SceneView& view, const Ray& ray, uint32_t n) {
    double sum = 0, sum2 = 0, collisions = 0;
    for (uint32_t i = 0; i < n; ++i) {
        SampleStream rng{7, i, 0};
        const double T = cloudTransmittance(view, ray, CloudOctaves{}, rng);
        sum += T;
        sum2 += T * T;
        float t;
        collisions += cloudCollision(view, ray, ray.tmax, rng, t);
    }
    const double mean = sum / n;
    return {mean, std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n), collisions / n};
}

} // namespace

// Ratio tracking through a homogeneous shell equals exp(-sigma d) for the chord d between its spheres
// (in double) within 1 % and four standard errors, and delta tracking collides with probability
// 1 - exp(-sigma d) within four standard errors: from the ground straight up and at 60 degrees from
// the zenith; from orbit straight down through the whole planet (two pieces: in and out of the
// shell on both sides); along the horizon from inside the shell (a chord of 113 km).
TEST(PlanetClouds, ShellTransmittanceIsBeerLambertAlongItsChords) {
    PlanetShape shape;
    shape.seaLevel = 400.0f;
    shape.amplitude = 100.0f;  // the ground under the camera is the sea, within 100 m
    const CloudLayer layer = uniformShell(2e-4f);
    const double bottom = shape.radius + shape.seaLevel + layer.bottom, top = bottom + layer.thickness;
    struct Case {
        double altitude;   // of the camera above the ground
        Vec3f dir;
        float sigma;
    };
    const float c60 = 0.5f, s60 = std::sqrt(0.75f);
    const Case cases[] = {{1000.0, {0, 1, 0}, 2e-4f},
                          {1000.0, {s60, c60, 0}, 2e-4f},
                          {1.2e7, {0, -1, 0}, 2e-4f},
                          {3000.0, {1, 0, 0}, 1e-5f}};
    for (const Case& c : cases) {
        CloudLayer l = layer;
        l.density = c.sigma;
        const Scene scene = planetWithClouds(shape, c.altitude, l);
        const SceneView view = scene.view();
        const double r0 = shape.radius + double(view.planets[0].cameraAltitude);
        // Upwards (or along the horizon) from inside the top sphere: from the bottom sphere (or the
        // camera inside the shell) to the top one. Straight down from orbit: twice the thickness.
        const double chord = c.dir.y >= 0.0f ? outwardChord(r0, c.dir.y, top) - (r0 < bottom ? outwardChord(r0, c.dir.y, bottom) : 0.0)
                                             : 2.0 * double(layer.thickness);
        const Estimates e = track(view, Ray{{0, 0, 0}, c.dir}, 100000);
        const double expected = std::exp(-double(c.sigma) * chord);
        EXPECT_NEAR(e.transmittance, expected, 0.01 * expected) << "camera at " << c.altitude << " m, chord " << chord;
        EXPECT_NEAR(e.transmittance, expected, 4.0 * e.error) << "camera at " << c.altitude << " m";
        const double p = 1.0 - expected;
        EXPECT_NEAR(e.collided, p, 4.0 * std::sqrt(p * (1.0 - p) / 100000.0)) << "camera at " << c.altitude << " m";
    }
}

// The shell's clouds belong to the planet, not to the camera: the density at 4000 points of the shell
// over 40 km around one camera equals the density at the same planet-fixed points seen from a camera
// a kilometre away and 500 m higher (camera-relative frames that differ), up to the float rounding of
// planet-fixed positions (0.5 m); a cumulus shell at coverage 0.5 covers some of them and never
// exceeds its majorant, the layer's density.
TEST(PlanetClouds, ShellCloudsStayWithThePlanetAsTheCameraMoves) {
    PlanetShape shape;
    shape.seaLevel = 400.0f;
    CloudLayer layer;
    layer.coverage = 0.5f;
    const Scene a = planetWithClouds(shape, 1000.0, layer, 20.0, 10.0);
    const Scene b = planetWithClouds(shape, 1500.0, layer, 20.005, 10.005);
    const SceneView va = a.view(), vb = b.view();
    const PlanetRecord &pa = va.planets[0], &pb = vb.planets[0];
    const CloudTables ta = cloudTables(va), tb = cloudTables(vb);
    const CloudLayer& built = va.cloudLayers[0];
    uint32_t cloudy = 0, close = 0;
    double sumDifference = 0, sumDensity = 0;
    const uint32_t n = 4000;
    for (uint32_t i = 0; i < n; ++i) {
        SampleStream rng{3, i, 0};
        const Vec3f pA{(rng.draw() - 0.5f) * 40000.0f, 0.0f, (rng.draw() - 0.5f) * 40000.0f};
        // Lift the point into the shell along its own vertical.
        const float altitude = float(shape.seaLevel) + built.bottom + rng.draw() * built.thickness;
        const Vec3f zenith = planetZenithOf(pa, pA);
        const Vec3f p = pA + zenith * (altitude - planetAltitude(pa, pA));
        const Vec3f q = planetFixedPosition(pa, p);
        // The same planet-fixed point in b's frame, in double: world = planet^T q - centre offset.
        double w[3] = {0, 0, 0};
        for (int r = 0; r < 3; ++r)
            for (int k = 0; k < 3; ++k) w[k] += double(pb.planetFromWorld[r][k]) * double(q[r]);
        const Vec3f pB{float(w[0] - double(pb.up.x) * double(pb.centreDistance)),
                       float(w[1] - double(pb.up.y) * double(pb.centreDistance)),
                       float(w[2] - double(pb.up.z) * double(pb.centreDistance))};
        const float dA = cloudShellDensity(built, ta, pa, p), dB = cloudShellDensity(vb.cloudLayers[0], tb, pb, pB);
        EXPECT_LE(dA, built.density);
        cloudy += dA > 0.0f;
        close += std::fabs(dA - dB) < 0.05f * built.density;
        sumDifference += std::fabs(dA - dB);
        sumDensity += dA;
    }
    EXPECT_GT(cloudy, n / 20) << "the shell has clouds over the camera";
    EXPECT_GT(close, n * 98 / 100);
    EXPECT_LT(sumDifference, 0.02 * sumDensity);
}
