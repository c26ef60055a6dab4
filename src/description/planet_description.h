// The scene description of a whole planet (docs/planets.md): with one, `urbis render` draws the
// planet instead of a city. Scene file key `planet`; --planet and --camera-orbit on the command line.
#pragma once

#include "math/vec.h"

#include <cstdint>

namespace urbis {

/// Where the camera above a planet is and where it looks.
struct PlanetCameraDescription {
    double altitudeKm = 12000.0;   ///< above the ground under the camera (the terrain or the sea, the higher)
    double lat = 20.0, lon = 10.0; ///< degrees, of the point under the camera
    float heading = 0.0f;          ///< degrees clockwise from north
    float pitch = -90.0f;          ///< degrees above the horizon (-90: straight down)
};

/// A planet: a sphere with an fBm heightfield, oceans and the atmosphere; Earth-like by default.
struct PlanetDescription {
    double radiusKm = 6360.0;                   ///< the base sphere
    float seaLevel = 400.0f;                    ///< metres above the base sphere
    float amplitude = 8000.0f;                  ///< metres: the terrain's heights lie within +- this
    float wavelengthKm = 4000.0f;               ///< of the fBm's first octave; each next one halves it
    float gain = 0.5f;                          ///< amplitude ratio of successive octaves
    uint32_t octaves = 20;
    uint32_t seed = 1;
    Vec3f oceanColour{0.01f, 0.03f, 0.07f};     ///< the sea's diffuse albedo, linear
    float atmosphereScale = 1.0f;               ///< the atmosphere's thickness over Earth's 100 km (optical depths kept)
    PlanetCameraDescription camera;
};

} // namespace urbis
