#include "planet/planet_build.h"

#include "geometry/planet_terrain.h"
#include "lights/light_build.h"
#include "math/constants.h"
#include "media/atmosphere_build.h"

#include <algorithm>
#include <cmath>

namespace urbis {

PlanetRecord makePlanetRecord(const PlanetShape& shape, const PlanetCameraPlacement& placement, uint32_t height,
                              uint32_t materials) {
    PlanetRecord pl{};
    const double lat = placement.lat * kPi / 180.0, lon = placement.lon * kPi / 180.0;
    // The camera's zenith, east and north in the planet-fixed frame (y the north pole).
    const double n[3] = {std::cos(lat) * std::sin(lon), std::sin(lat), std::cos(lat) * std::cos(lon)};
    const double east[3] = {std::cos(lon), 0.0, -std::sin(lon)};
    const double north[3] = {-std::sin(lat) * std::sin(lon), std::cos(lat), -std::sin(lat) * std::cos(lon)};
    // planetFromWorld's columns are the world's x (east), y (up) and z (south) in the planet frame.
    for (int i = 0; i < 3; ++i) pl.planetFromWorld[i] = Vec3f{float(east[i]), float(n[i]), float(-north[i])};
    pl.up = {0, 1, 0};
    pl.radius = float(shape.radius);
    pl.seaLevel = shape.seaLevel;
    pl.amplitude = shape.amplitude;
    pl.baseFrequency = 1.0f / shape.wavelength;
    pl.gain = shape.gain;
    pl.octaves = std::min(shape.octaves, kPlanetMaxOctaves);
    pl.seed = shape.seed;
    pl.materials = materials;
    double norm = 0.0, amplitude = 1.0;
    for (uint32_t i = 0; i < pl.octaves; ++i, amplitude *= shape.gain) norm += amplitude;
    pl.heightScale = float(shape.amplitude / norm);
    // The lattice at the camera's point of the base sphere, split in double: what float could not hold.
    for (uint32_t i = 0; i < pl.octaves; ++i) {
        const double frequency = std::ldexp(1.0 / double(shape.wavelength), int(i));
        for (int a = 0; a < 3; ++a) {
            const double x = shape.radius * n[a] * frequency, fl = std::floor(x);
            pl.cell[i][a] = int32_t(uint32_t(int64_t(fl)));
            pl.frac[i][a] = float(x - fl);
        }
    }
    const double tanHalf = std::tan(0.5 * placement.fov * kPi / 180.0);
    pl.lodAngle = float(2.0 * tanHalf / double(std::max(height, 1u)));
    // The ground under the camera: the heightfield is a function of direction, so its height at the
    // camera's own point (p = 0) does not depend on the camera's altitude.
    pl.centreDistance = pl.radius;
    Vec3f zenith;
    const double ground = std::max(double(planetHeight(pl, {0, 0, 0}, zenith)), double(shape.seaLevel));
    const double cameraAltitude = ground + placement.altitude;
    pl.cameraAltitude = float(cameraAltitude);
    pl.centreDistance = float(shape.radius + cameraAltitude);
    pl.lipschitz = planetTerrainLipschitz(pl);
    return pl;
}

float planetTerrainLipschitz(const PlanetRecord& pl) {
    const double bottom = double(pl.radius) - double(pl.amplitude);
    double slopes = 0.0, fade = 0.0, amplitude = 1.0, frequency = pl.baseFrequency;
    for (uint32_t i = 0; i < pl.octaves; ++i, amplitude *= pl.gain, frequency *= 2.0) {
        slopes += amplitude * frequency * kValueNoiseSlope;
        // Octave i fades where the distance d from the camera is at least 1 / (2 f_i lodAngle), at a
        // rate 1 / (d ln 2): only one octave fades at any distance.
        fade = std::max(fade, amplitude * 2.0 * frequency * double(pl.lodAngle) / std::log(2.0));
    }
    const double stretch = double(pl.radius) / bottom;  // from the base sphere down to the shell's bottom
    const double weights = 2.0 * std::sqrt(3.0) / (1.0 / std::sqrt(3.0) - double(kTriplanarCut)) *
                           double(pl.amplitude) / bottom;
    return float(1.0 + double(pl.heightScale) * (slopes * stretch + fade) + weights);
}

std::vector<Material> planetMaterials(Vec3f oceanColour) {
    std::vector<Material> m(size_t(PlanetMaterial::Count));
    Material& ocean = m[size_t(PlanetMaterial::Ocean)];
    ocean.kind = MaterialKind::Glossy;  // a smooth sea: the sun's glint as a sharp lobe that light samples find
    ocean.albedo = oceanColour;
    ocean.specular = {0.06f, 0.06f, 0.06f};
    ocean.exponent = 600.0f;
    m[size_t(PlanetMaterial::Sand)].albedo = {0.50f, 0.42f, 0.30f};
    m[size_t(PlanetMaterial::Vegetation)].albedo = {0.07f, 0.12f, 0.04f};
    m[size_t(PlanetMaterial::Rock)].albedo = {0.22f, 0.19f, 0.16f};
    m[size_t(PlanetMaterial::Snow)].albedo = {0.85f, 0.87f, 0.90f};
    return m;
}

Sky planetSky(const Sky& sky, const PlanetRecord& pl, float scale) {
    Sky out = sky;
    Atmosphere& a = out.atmosphere;
    const float thickness = (a.topRadius - a.bottomRadius) * scale;
    a.bottomRadius = (pl.radius + pl.seaLevel) * 1e-3f;
    a.topRadius = a.bottomRadius + thickness;
    a.rayleighScaleHeight *= scale;
    a.mieScaleHeight *= scale;
    a.ozoneCentre *= scale;
    a.ozoneHalfWidth *= scale;
    a.rayleighScattering = a.rayleighScattering * (1.0f / scale);
    a.mieScattering /= scale;
    a.mieAbsorption /= scale;
    a.ozoneAbsorption = a.ozoneAbsorption * (1.0f / scale);
    a.altitude = std::max(0.0f, (pl.cameraAltitude - pl.seaLevel) * 1e-3f);
    return out;
}

Camera planetCamera(const PlanetCameraPlacement& placement, float aspect) {
    const float h = placement.heading * float(kPi) / 180.0f, p = placement.pitch * float(kPi) / 180.0f;
    Camera c;
    c.position = {0, 0, 0};
    c.forward = normalize(Vec3f{std::cos(p) * std::sin(h), std::sin(p), -std::cos(p) * std::cos(h)});
    c.right = Vec3f{std::cos(h), 0.0f, std::sin(h)};  // horizontal, a quarter turn clockwise from the heading
    c.up = cross(c.right, c.forward);
    c.tanHalfFovY = std::tan(0.5f * placement.fov * float(kPi) / 180.0f);
    c.aspect = aspect;
    return c;
}

Scene buildPlanetScene(const PlanetRecord& pl, Vec3f oceanColour, const Sun& sun, const NightSky& night, const Sky& sky) {
    Scene scene = Scene::build({.materials = planetMaterials(oceanColour), .planets = {pl}});
    scene.sun = sun;
    scene.night = night;
    scene.sky = sky;
    buildAtmosphere(scene);
    scene.sun = sun;  // its radiance at the top of the atmosphere (diskTransmittanceFrom)
    LightBuildOptions lights;
    lights.sky = false;
    buildLights(scene, lights);
    return scene;
}

} // namespace urbis
