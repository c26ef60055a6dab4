// A whole planet around a camera (host): its record with everything that would cancel in float
// worked out in double (the camera's altitude, the noise lattice at the camera's point, the
// Lipschitz bound of the march), and its scene: the record, its materials, the atmosphere around it
// and the sun. docs/planets.md.
#pragma once

#include "scene/camera.h"
#include "scene/scene.h"

namespace urbis {

/// The planet's shape, metres.
struct PlanetShape {
    double radius = 6.36e6;        ///< of the base sphere
    float seaLevel = 0.0f;         ///< above the base sphere
    float amplitude = 8000.0f;     ///< the terrain's height lies in [-amplitude, amplitude]
    float wavelength = 4.0e6f;     ///< of the fBm's first octave; each next one halves it
    float gain = 0.5f;             ///< amplitude ratio of successive octaves
    uint32_t octaves = 20;
    uint32_t seed = 1;
};

/// Where the camera is and where it looks.
struct PlanetCameraPlacement {
    double lat = 20.0, lon = 10.0;  ///< degrees, of the point under the camera
    double altitude = 1.2e7;        ///< metres above the ground under the camera (the terrain or the sea, the higher)
    float heading = 0.0f;           ///< degrees clockwise from north
    float pitch = -90.0f;           ///< degrees above the horizon (-90: straight down)
    float fov = 50.0f;              ///< vertical field of view, degrees
};

/// The planet's record around a camera at `placement` for an image `height` pixels high (the
/// heightfield's level of detail: octaves under two pixels fade out), its materials from `materials`.
PlanetRecord makePlanetRecord(const PlanetShape& shape, const PlanetCameraPlacement& placement, uint32_t height,
                              uint32_t materials);

/// A bound of |grad| of planetTerrainDistance over the shell that holds the terrain: 1 (the altitude)
/// plus the octaves' slopes (kValueNoiseSlope x frequency x amplitude each) stretched from the base
/// sphere to the shell's bottom, the triplanar weights' change, and the level of detail's fade.
float planetTerrainLipschitz(const PlanetRecord& pl);

/// The planet's materials (PlanetMaterial order), the ocean of `oceanColour`.
std::vector<Material> planetMaterials(Vec3f oceanColour);

/// What the atmosphere around a planet is: the city's `sky` (Earth's, docs/atmosphere.md) with its
/// ground sphere at the planet's sea level and its heights times `scale` (its coefficients over it,
/// so that every optical depth stays Earth's).
Sky planetSky(const Sky& sky, const PlanetRecord& pl, float scale);

/// The camera at the world's origin looking along `placement`'s heading and pitch (world: x east,
/// y the local zenith, z south), never degenerate looking straight down.
Camera planetCamera(const PlanetCameraPlacement& placement, float aspect);

/// The scene of one planet under `sun`: the record, its materials, the atmosphere's tables (the sun's
/// and moon's radiance kept as at the top of the atmosphere: each ray takes its own transmittance),
/// and the lights (the sun; the sky is found by BSDF sampling, since its radiance depends on where
/// it is seen from).
Scene buildPlanetScene(const PlanetRecord& pl, Vec3f oceanColour, const Sun& sun, const NightSky& night, const Sky& sky);

} // namespace urbis
