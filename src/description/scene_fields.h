// The one list of a scene file's keys: each field of SceneDescription with its JSON name and its
// allowed range. The reader and the writer (scene_json.cpp) both walk it, so a saved file has every
// key and a key the list lacks is unknown to the reader.
#pragma once

#include "description/scene_description.h"
#include "description/terrain_fields.h"

#include <span>
#include <utility>

namespace urbis {

/// Names of the geometry representations, for the scene file.
inline constexpr std::pair<const char*, Representation> kRepresentationNames[] = {
    {"procedural", Representation::Procedural}, {"triangles", Representation::Triangles}, {"plain", Representation::Plain}};

/// Calls the visitor `v` on every field of `d` (a SceneDescription, const or not), in file order:
///   v.object(key, fn)                           a nested object; fn() visits its fields
///   v.optionalObject(key, optional, fn)         an object or null; fn(value) visits its fields
///   v.number(key, value, lo, hi)                an integer or a float in [lo, hi]
///   v.vec3(key, vec, lo, hi) / v.optionalVec3   three numbers, each in [lo, hi] (or null)
///   v.optionalArray(key, optional, lo, hi)      N numbers in [lo, hi], or null
///   v.text(key, string)                         any string
///   v.boolean(key, flag)                        true or false
///   v.choice(key, string, names)                one of `names`
///   v.choiceList(key, strings, names)           an array of distinct `names`
///   v.enumeration(key, value, pairs)            one of the names of `pairs`
///   v.colourMap(key, map)                       an object of building type -> colour
///   v.animation(key, animation)                 the keyframes (description/animation_json.h)
template <typename Description, typename Visitor>
void visitSceneFields(Description& d, Visitor& v) {
    v.object("source", [&] {
        v.text("osm", d.source.osm);
        v.optionalArray("bbox", d.source.bbox, -180.0, 180.0);
        v.optionalArray("height_range", d.source.heightRange, 0.0f, 1000.0f);
        v.number("metres_per_level", d.source.metresPerLevel, 1.0f, 20.0f);
        v.number("height_scale", d.source.heightScale, 0.05f, 50.0f);
        v.number("buildings", d.source.buildings, uint64_t(1), kMaxDescribedBuildings);
        v.number("seed", d.source.seed, 0u, UINT32_MAX);
    });
    v.object("camera", [&] {
        v.optionalVec3("position", d.camera.position, -1e7f, 1e7f);
        v.optionalVec3("target", d.camera.target, -1e7f, 1e7f);
        v.optionalObject("geo", d.camera.geo, [&](auto& geo) {
            v.number("lon", geo.lon, -180.0, 180.0);
            v.number("lat", geo.lat, -90.0, 90.0);
            v.number("altitude", geo.altitude, -1e5f, 1e7f);
            v.number("heading", geo.heading, -360.0f, 360.0f);
            v.number("pitch", geo.pitch, -90.0f, 90.0f);
            v.boolean("above_ground", geo.aboveGround);
        });
        v.number("fov", d.camera.fov, 1.0f, 170.0f);
    });
    v.object("sun", [&] {
        v.number("elevation", d.sun.elevation, -90.0f, 90.0f);
        v.number("azimuth", d.sun.azimuth, -360.0f, 360.0f);
        v.number("angular_radius", d.sun.angularRadius, 0.01f, 20.0f);
        v.vec3("irradiance", d.sun.irradiance, 0.0f, 1e6f);
    });
    v.object("astronomy", [&] {
        v.text("time", d.astronomy.time);
        v.optionalArray("location", d.astronomy.location, -180.0, 180.0);
        v.boolean("sun_from_time", d.astronomy.sunFromTime);
    });
    v.object("sky", [&] {
        v.vec3("zenith", d.sky.zenith, 0.0f, 1e6f);
        v.vec3("horizon", d.sky.horizon, 0.0f, 1e6f);
        v.vec3("ground", d.sky.ground, 0.0f, 1e6f);
        v.number("exponent", d.sky.exponent, 0.01f, 100.0f);
        v.choice("model", d.sky.model, std::span(kSkyModels));
        v.number("aerosols", d.sky.aerosols, 0.0f, 100.0f);
        v.number("ozone", d.sky.ozone, 0.0f, 10.0f);
        v.number("mie_anisotropy", d.sky.mieAnisotropy, 0.0f, 0.99f);
        v.vec3("ground_albedo", d.sky.groundAlbedo, 0.0f, 1.0f);
        v.number("altitude", d.sky.altitude, -500.0f, 9000.0f);
        v.boolean("aerial_perspective", d.sky.aerialPerspective);
    });
    v.object("lights", [&] { v.number("hour", d.lights.hour, -1.0f, 24.0f); });
    v.object("materials", [&] {
        v.object("ground", [&] { v.vec3("albedo", d.materials.city.groundAlbedo, 0.0f, 1.0f); });
        v.object("window_glass", [&] {
            v.vec3("transmittance", d.materials.city.glassTransmittance, 0.0f, 1.0f);
            v.number("ior", d.materials.city.glassIor, 1.0f, 3.0f);
        });
        v.object("lit_room", [&] { v.vec3("emission", d.materials.city.litRoomEmission, 0.0f, 1e6f); });
        v.colourMap("wall_colour_by_type", d.materials.wallColourByType);
        v.colourMap("roof_colour_by_type", d.materials.roofColourByType);
    });
    v.object("geometry", [&] {
        v.enumeration("walls", d.geometry.modes.walls, kRepresentationNames);
        v.enumeration("roofs", d.geometry.modes.roofs, kRepresentationNames);
        v.enumeration("lamps", d.geometry.modes.lamps, kRepresentationNames);
        v.text("wall_tiles", d.geometry.wallTiles);
        v.boolean("streets", d.geometry.streets);
        v.choice("traffic", d.geometry.traffic, std::span(kTrafficSides));
        v.enumeration("trees", d.geometry.modes.trees, kRepresentationNames);
    });
    v.object("integrator", [&] {
        v.choice("kind", d.integrator.kind, std::span(kIntegratorKinds));
        v.number("spp", d.integrator.spp, 1u, kMaxSpp);
        v.number("seed", d.integrator.seed, 0u, UINT32_MAX);
        v.number("max_depth", d.integrator.maxDepth, 1u, 1000u);
        v.number("rr_depth", d.integrator.rrDepth, 1u, 1000u);
        v.number("rr_survival", d.integrator.rrSurvival, 0.01f, 1.0f);
        v.choice("light_sampler", d.integrator.lightSampler, std::span(kLightSamplers));
        v.number("light_samples", d.integrator.lightSamples, 0u, 64u);
    });
    v.object("film", [&] {
        v.number("width", d.film.width, 1u, kMaxImageSide);
        v.number("height", d.film.height, 1u, kMaxImageSide);
        v.number("exposure", d.film.exposure, -20.0f, 20.0f);
        v.text("output", d.film.output);
        v.choiceList("layers", d.film.layers, std::span(kFilmLayerNames));
        v.boolean("exr_float", d.film.exrFloat);
        v.boolean("denoise", d.film.denoise);
    });
    v.object("terrain", [&] { visitTerrainFields(d.terrain, v); });
    v.object("water", [&] {
        v.boolean("enabled", d.water.enabled);
        v.number("max_depth", d.water.maxDepth, 0.0f, 1000.0f);
        v.number("shelf_width", d.water.shelfWidth, 0.0f, 10000.0f);
        v.number("bank_slope", d.water.bankSlope, 0.01f, 1000.0f);
        v.vec3("absorption", d.water.absorption, 0.0f, 100.0f);
        v.vec3("bed_albedo", d.water.bedAlbedo, 0.0f, 1.0f);
        v.number("wind_speed", d.water.windSpeed, 0.0f, 60.0f);
        v.number("wind_from", d.water.windFrom, -360.0f, 360.0f);
    });
    v.object("trees", [&] {
        v.boolean("enabled", d.trees.enabled);
        v.number("seed", d.trees.seed, 0u, UINT32_MAX);
        v.number("forest_density", d.trees.forestDensity, 0.0f, 5000.0f);
        v.number("park_density", d.trees.parkDensity, 0.0f, 5000.0f);
        v.number("scrub_density", d.trees.scrubDensity, 0.0f, 5000.0f);
        v.number("outer_forest", d.trees.outerForest, 0.0f, 30000.0f);
        v.number("outer_forest_cell", d.trees.outerForestCell, 1.0f, 100.0f);
        v.number("outer_forest_density", d.trees.outerForestDensity, 0.0f, 10000.0f);
        v.number("clearance", d.trees.clearance, 0.0f, 50.0f);
        v.number("default_height", d.trees.defaultHeight, 1.0f, 150.0f);
        v.number("size_variation", d.trees.sizeVariation, 0.0f, 0.9f);
        v.number("conifer_share", d.trees.coniferShare, 0.0f, 1.0f);
        v.number("roughness", d.trees.roughness, 0.0f, 1.0f);
        v.number("lumps", d.trees.lumps, 0.1f, 10.0f);
        v.choice("season", d.trees.season, std::span(kTreeSeasons));
        v.vec3("bark_albedo", d.trees.barkAlbedo, 0.0f, 1.0f);
        v.vec3("leaf_albedo", d.trees.leafAlbedo, 0.0f, 1.0f);
        v.vec3("needle_albedo", d.trees.needleAlbedo, 0.0f, 1.0f);
        v.vec3("autumn_albedo", d.trees.autumnAlbedo, 0.0f, 1.0f);
    });
    v.object("photons", [&] {
        v.number("per_pass", d.photons.perPass, 1u, 1u << 26);
        v.number("radius", d.photons.radius, 1e-3f, 1e3f);
        v.number("alpha", d.photons.alpha, 0.01f, 1.0f);
        v.number("texel", d.photons.texel, 0.01f, 100.0f);
        v.number("level_distance", d.photons.levelDistance, 0.1f, 1e5f);
    });
    v.optionalObject("planet", d.planet, [&](auto& p) {
        v.number("radius_km", p.radiusKm, 10.0, 1e6);
        v.number("sea_level", p.seaLevel, -1e5f, 1e5f);
        v.number("amplitude", p.amplitude, 0.0f, 1e5f);
        v.number("wavelength_km", p.wavelengthKm, 0.01f, 1e6f);
        v.number("gain", p.gain, 0.05f, 0.95f);
        v.number("octaves", p.octaves, 1u, 24u);
        v.number("seed", p.seed, 0u, UINT32_MAX);
        v.vec3("ocean_colour", p.oceanColour, 0.0f, 1.0f);
        v.number("atmosphere_scale", p.atmosphereScale, 0.001f, 100.0f);
        v.object("camera", [&] {
            v.number("altitude_km", p.camera.altitudeKm, 0.0, 1e6);
            v.number("lat", p.camera.lat, -90.0, 90.0);
            v.number("lon", p.camera.lon, -360.0, 360.0);
            v.number("heading", p.camera.heading, -360.0f, 360.0f);
            v.number("pitch", p.camera.pitch, -90.0f, 90.0f);
        });
    });
    v.object("clouds", [&] {
        auto& c = d.clouds.layer;
        v.number("coverage", c.coverage, 0.0f, 1.0f);
        v.choice("type", d.clouds.type, std::span(kCloudTypes));
        v.number("altitude", c.bottom, -500.0f, 20000.0f);
        v.number("thickness", c.thickness, 10.0f, 20000.0f);
        v.number("density", c.density, 1e-6f, 10.0f);
        v.number("albedo", c.albedo, 0.0f, 1.0f);
        v.number("scale", c.scale, 100.0f, 1e6f);
        v.number("radius", c.radius, 100.0f, 1e7f);
        v.vec3("wind", c.wind, -1e7f, 1e7f);
        v.number("seed", c.seed, 0u, UINT32_MAX);
        v.number("phase_forward", c.forwardG, 0.0f, 0.99f);
        v.number("phase_backward", c.backwardG, -0.99f, 0.0f);
        v.number("phase_blend", c.forwardWeight, 0.0f, 1.0f);
        v.number("octaves", c.octaves, 1u, kCloudMaxOctaves);
        v.number("octave_scattering", c.octaveScattering, 0.0f, 1.0f);
        v.number("octave_extinction", c.octaveExtinction, 0.0f, 1.0f);
        v.number("octave_anisotropy", c.octaveAnisotropy, 0.0f, 1.0f);
    });
    v.animation("animation", d.animation);
}

} // namespace urbis
