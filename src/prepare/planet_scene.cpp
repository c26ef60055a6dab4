#include "prepare/planet_scene.h"

#include "base/step_timer.h"
#include "description/celestial_parts.h"
#include "description/scene_parts.h"
#include "media/cloud_build.h"
#include "planet/planet_build.h"


namespace urbis {

PreparedScene preparePlanetScene(const SceneDescription& d) {
    const auto t0 = SteadyClock::now();
    const PlanetDescription& p = *d.planet;
    PlanetShape shape;
    shape.radius = p.radiusKm * 1e3;
    shape.seaLevel = p.seaLevel;
    shape.amplitude = p.amplitude;
    shape.wavelength = p.wavelengthKm * 1e3f;
    shape.gain = p.gain;
    shape.octaves = p.octaves;
    shape.seed = p.seed;
    PlanetCameraPlacement placement;
    placement.lat = p.camera.lat;
    placement.lon = p.camera.lon;
    placement.altitude = p.camera.altitudeKm * 1e3;
    placement.heading = p.camera.heading;
    placement.pitch = p.camera.pitch;
    placement.fov = d.camera.fov;
    const PlanetRecord record = makePlanetRecord(shape, placement, d.film.height, 0);
    // The sun and the moon as seen from the point under the camera (with a time: at its lat, lon).
    const CelestialLights celestial = celestialLightsOf(d, GeoOrigin{true, p.camera.lat, p.camera.lon});
    PreparedScene prepared;
    prepared.scene = buildPlanetScene(record, p.oceanColour, celestial.sun, celestial.night,
                                      planetSky(skyOf(d.sky), record, p.atmosphereScale));
    buildClouds(prepared.scene, cloudLayerOf(d.clouds));  // the shell around the planet (media/cloud_shell.h)
    prepared.camera = planetCamera(placement, float(d.film.width) / float(d.film.height));
    prepared.summary.source = "planet";
    prepared.secondsBvh = secondsSince(t0);
    return prepared;
}

} // namespace urbis
