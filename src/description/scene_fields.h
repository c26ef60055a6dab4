// The one list of a scene file's keys: each field of SceneDescription with its JSON name, its range,
// the command-line option that sets it, its help and how far a change of it reaches (Field,
// description/scene_field.h). The reader and the writer (scene_json.cpp), the command line
// (app/scene_options.cpp) and the viewer's panel (viewer/view_panel.cpp) all walk it, so a key added
// here is in the file, on the command line and in the panel, and a key the list lacks is unknown.
#pragma once

#include "description/animation_fields.h"
#include "description/scene_description.h"
#include "description/scene_field.h"
#include "description/terrain_fields.h"

namespace urbis {

/// Calls the visitor `v` on every field of `d` (a SceneDescription, const or not), in file order:
///   v.object(key, fn)                           a nested object; fn() visits its fields
///   v.optionalObject(field, optional, fn)       an object or null; fn(value) visits its fields
///   v.number(field, value, lo, hi)              an integer or a float in [lo, hi]
///   v.vec3(field, vec, lo, hi) / v.optionalVec3 three numbers, each in [lo, hi] (or null)
///   v.optionalArray(field, optional, lo, hi)    N numbers in [lo, hi], or null
///   v.text(field, string)                       any string
///   v.boolean(field, flag)                      true or false
///   v.choice(field, string, table)              one of the names of `table` (base/choice.h)
///   v.choiceList(field, strings, names)         an array of distinct `names`
///   v.enumeration(field, value, table)          the value of one of the Choices of `table`
///   v.colourMap(field, map)                     an object of building type -> colour
///   v.keyframes(field, keyframes)               an array of keyframes (description/animation_json.h)
/// Each `field` is a Field; a key without a range of its own names its limits in the help.
template <typename Description, typename Visitor>
void visitSceneFields(Description& d, Visitor& v) {
    using enum SceneChange;
    v.object("source", [&] {
        v.text({"osm", "--osm", "OpenStreetMap file: .osm, .osm.pbf, .osm.bz2, .osm.gz (default: the generated city)"},
               d.source.osm);
        v.optionalArray({"bbox", "--bbox", "OSM crop MINLON, MINLAT, MAXLON, MAXLAT (none: the file's header box)"},
                        d.source.bbox, -180.0, 180.0);
        v.optionalArray({"height_range", "--building-height-range", "MIN, MAX metres of buildings without height tags"},
                        d.source.heightRange, 0.0f, 1000.0f);
        v.number({"metres_per_level", "--metres-per-level", "Storey height for building:levels"}, d.source.metresPerLevel,
                 1.0f, 20.0f);
        v.number({"height_scale", "--height-scale", "Multiply every building's height (and min height)"},
                 d.source.heightScale, 0.05f, 50.0f);
        v.number({"buildings", "--buildings", "Buildings in the generated city"}, d.source.buildings, uint64_t(1),
                 kMaxDescribedBuildings);
        v.number({"seed", "--seed", "Seed of the city and of the sampler"}, d.source.seed, 0u,
                 UINT32_MAX);
    });
    v.object("camera", [&] {
        v.optionalVec3({"position", "--camera", "Camera position, world metres", Restart}, d.camera.position, -1e7f, 1e7f);
        v.optionalVec3({"target", "--camera", "The point looked at, world metres", Restart}, d.camera.target, -1e7f, 1e7f);
        v.optionalObject({"geo", "--camera-geo", "A geographic placement (OSM only)", Restart}, d.camera.geo, [&](auto& geo) {
            v.number({"lon", "--camera-geo", "Longitude, degrees WGS84", Restart}, geo.lon, -180.0, 180.0);
            v.number({"lat", "--camera-geo", "Latitude, degrees WGS84", Restart}, geo.lat, -90.0, 90.0);
            v.number({"altitude", "--camera-geo", "Metres above the ground plane (sea level on a DEM)", Restart},
                     geo.altitude, -1e5f, 1e7f);
            v.number({"heading", "--camera-geo", "Degrees clockwise from north", Restart}, geo.heading, -360.0f, 360.0f);
            v.number({"pitch", "--camera-geo", "Degrees above the horizon; negative looks down", Restart}, geo.pitch, -90.0f,
                     90.0f);
            v.boolean({"above_ground", "--camera-geo", "Altitude above the terrain under the camera instead", Restart},
                      geo.aboveGround);
        });
        v.number({"fov", "--fov", "Vertical field of view, degrees", Restart}, d.camera.fov, 1.0f, 170.0f);
    });
    v.object("sun", [&] {
        v.number({"elevation", "--sun", "Degrees above the horizon", Relight}, d.sun.elevation, -90.0f, 90.0f);
        v.number({"azimuth", "--sun", "Degrees clockwise from north", Relight}, d.sun.azimuth, -360.0f, 360.0f);
        v.number({"angular_radius", "--sun-radius", "Angular radius of the sun, degrees", Relight}, d.sun.angularRadius,
                 0.01f, 20.0f);
        v.vec3({"irradiance", "--sun-irradiance", "R,G,B on a surface facing the sun, relative units", Relight},
               d.sun.irradiance, 0.0f, 1e6f);
    });
    v.object("astronomy", [&] {
        v.text({"time", "--time", "ISO 8601 date and time with a UTC offset or Z", Relight}, d.astronomy.time);
        v.optionalArray({"location", "--location", "LON, LAT degrees the sky is seen from", Relight}, d.astronomy.location,
                        -180.0, 180.0);
        v.boolean({"sun_from_time", "--sun-from-time", "With a time, the sun's direction comes from it", Relight},
                  d.astronomy.sunFromTime);
    });
    v.object("sky", [&] {
        v.vec3({"zenith", "--sky-zenith", "Analytic sky: R,G,B radiance straight up", Relight}, d.sky.zenith, 0.0f, 1e6f);
        v.vec3({"horizon", "--sky-horizon", "Analytic sky: R,G,B radiance at the horizon", Relight}, d.sky.horizon, 0.0f,
               1e6f);
        v.vec3({"ground", "--sky-ground", "Analytic sky: R,G,B radiance below the horizon", Relight}, d.sky.ground, 0.0f,
               1e6f);
        v.number({"exponent", "--sky-exponent", "Analytic sky: the zenith's weight is up^exponent", Relight},
                 d.sky.exponent, 0.01f, 100.0f);
        v.choice({"model", "--sky", "Sky model: atmosphere (Hillaire 2020) or analytic (a gradient)", Relight}, d.sky.model,
                 kSkyModels);
        v.number({"aerosols", "--sky-aerosols", "Atmosphere: scales the aerosols (1: clear air, 5 to 20: haze)", Relight},
                 d.sky.aerosols, 0.0f, 100.0f);
        v.number({"ozone", "--sky-ozone", "Atmosphere: scales the ozone's absorption", Relight}, d.sky.ozone, 0.0f, 10.0f);
        v.number({"mie_anisotropy", "--sky-mie-anisotropy", "Atmosphere: g of the aerosols' phase function", Relight},
                 d.sky.mieAnisotropy, 0.0f, 0.99f);
        v.vec3({"ground_albedo", "--sky-ground-albedo", "Atmosphere: R,G,B albedo of the planet's ground", Relight},
               d.sky.groundAlbedo, 0.0f, 1.0f);
        v.number({"altitude", "--sky-altitude", "Atmosphere: metres of the world's y = 0 above sea level", Relight},
                 d.sky.altitude, -500.0f, 9000.0f);
        v.boolean({"aerial_perspective", "--no-aerial-perspective",
                   "No haze along path segments (the atmosphere still gives the sky and the sun)", Relight},
                  d.sky.aerialPerspective);
    });
    v.object("lights", [&] {
        v.number({"hour", "--lights-hour", "Local clock hours that set which rooms are lit; negative: from the time or the sun",
                  Relight},
                 d.lights.hour, -1.0f, 24.0f);
    });
    v.object("materials", [&] {
        v.object("ground", [&] {
            v.vec3({"albedo", "--ground-albedo", "R,G,B diffuse reflectance of the ground"}, d.materials.city.groundAlbedo,
                   0.0f, 1.0f);
        });
        v.object("window_glass", [&] {
            v.vec3({"transmittance", "--glass-transmittance", "R,G,B tint of the light through a window pane"},
                   d.materials.city.glassTransmittance, 0.0f, 1.0f);
            v.number({"ior", "--glass-ior", "Index of refraction of the windows' panes"}, d.materials.city.glassIor, 1.0f,
                     3.0f);
        });
        v.object("lit_room", [&] {
            v.vec3({"emission", "--lit-room-emission", "R,G,B mean radiance of the lit rooms behind windows"},
                   d.materials.city.litRoomEmission, 0.0f, 1e6f);
        });
        v.colourMap({"wall_colour_by_type", "--wall-colour", "TYPE=R,G,B: wall colour of a building type whose tags name none"},
                    d.materials.wallColourByType);
        v.colourMap({"roof_colour_by_type", "--roof-colour", "TYPE=R,G,B: roof colour of a building type whose tags name none"},
                    d.materials.roofColourByType);
    });
    v.object("geometry", [&] {
        v.enumeration({"walls", "--geometry", "Facades: procedural, their triangle twin, or plain (none)"},
                      d.geometry.modes.walls, kRepresentations);
        v.enumeration({"roofs", "--geometry", "Roofs: procedural parapets of flat roofs, or triangles"},
                      d.geometry.modes.roofs, kRepresentations);
        v.enumeration({"lamps", "--geometry", "Street lamps: analytic shapes, or their triangle twin"},
                      d.geometry.modes.lamps, kRepresentations);
        v.text({"wall_tiles", "--wall-tiles", "whole, or SLOTSxFLOORS: BVH tiles of at most that many cells per wall"},
               d.geometry.wallTiles);
        v.boolean({"streets", "--no-streets", "Buildings on the bare ground: no roads, sidewalks, ground cover, water, lamps or trees"},
                  d.geometry.streets);
        v.choice({"traffic", "--traffic", "The side traffic keeps (lanes, stop lines): auto (by the city's place), right or left"},
                 d.geometry.traffic, kTrafficSides);
        v.enumeration({"trees", "--geometry", "Trees: sphere traced from their distance function, or their triangle twin"},
                      d.geometry.modes.trees, kRepresentations);
    });
    v.object("integrator", [&] {
        v.choice({"kind", "--integrator",
                  "The integrator: the path tracer, or indirect light from per-block photon buffers or a hash-grid "
                  "photon map, the reference (docs/photons.md)",
                  Restart},
                 d.integrator.kind, kIntegratorKinds);
        v.number({"spp", "--spp", "Samples per pixel", Restart}, d.integrator.spp, 1u, kMaxSpp);
        v.number({"seed", "--seed", "Seed of the sampler", Restart}, d.integrator.seed, 0u, UINT32_MAX);
        v.number({"max_depth", "--max-depth", "Path vertices after the camera", Restart}, d.integrator.maxDepth, 1u, 1000u);
        v.number({"rr_depth", "--rr-depth", "Depth where Russian roulette starts", Restart}, d.integrator.rrDepth, 1u,
                 1000u);
        v.number({"rr_survival", "--rr-survival", "Largest survival probability of Russian roulette", Restart},
                 d.integrator.rrSurvival, 0.01f, 1.0f);
        v.choice({"light_sampler", "--light-sampler",
                  "How lights are picked: uniform, power, bvh (the light BVH) or colliders (the thesis's)", Restart},
                 d.integrator.lightSampler, kLightSamplers);
        v.number({"light_samples", "--light-samples", "Light samples per path vertex (0: BSDF sampling alone)", Restart},
                 d.integrator.lightSamples, 0u, 64u);
    });
    v.object("film", [&] {
        v.number({"width", "--width", "Image width in pixels", Resize}, d.film.width, 1u, kMaxImageSide);
        v.number({"height", "--height", "Image height in pixels", Resize}, d.film.height, 1u, kMaxImageSide);
        v.number({"exposure", "--exposure", "Exposure in stops", Display}, d.film.exposure, -20.0f, 20.0f);
        v.text({"output", "--out",
                "Image to write; the format follows the extension: .png (tone-mapped sRGB) or .exr (linear, with AOV layers)",
                None},
               d.film.output);
        v.choiceList({"layers", "--exr-layers", "The AOV layers an .exr holds beside RGBA, NAME,... or none", None},
                     d.film.layers, kFilmLayerNames);
        v.boolean({"exr_float", "--exr-float", "EXR colour, albedo and normal as 32-bit float (default half)", None},
                  d.film.exrFloat);
        v.boolean({"denoise", "--denoise", "Denoise the HDR film, guided by its AOVs, before it is written", Display},
                  d.film.denoise);
    });
    v.object("terrain", [&] { visitTerrainFields(d.terrain, v); });
    v.object("water", [&] {
        v.boolean({"enabled", "--no-water", "No water surfaces or beds: the ground under them shows"}, d.water.enabled);
        v.number({"max_depth", "--water-max-depth", "Metres of the bed below the ground away from the shore"},
                 d.water.maxDepth, 0.0f, 1000.0f);
        v.number({"shelf_width", "--water-shelf-width", "Metres from the shore to where the bed reaches its depth"},
                 d.water.shelfWidth, 0.0f, 10000.0f);
        v.number({"bank_slope", "--water-bank-slope", "Rise over run of a river's banks on a terrain"}, d.water.bankSlope,
                 0.01f, 1000.0f);
        v.vec3({"absorption", "--water-absorption", "R,G,B per metre of light lost below the surface"}, d.water.absorption,
               0.0f, 100.0f);
        v.vec3({"bed_albedo", "--water-bed-albedo", "R,G,B diffuse colour of the bed"}, d.water.bedAlbedo, 0.0f, 1.0f);
        v.number({"wind_speed", "--water-wind-speed", "m/s of the wind that raises the waves (0: a mirror)"},
                 d.water.windSpeed, 0.0f, 60.0f);
        v.number({"wind_from", "--water-wind-from", "Degrees clockwise from north the wind blows from"}, d.water.windFrom,
                 -360.0f, 360.0f);
    });
    v.object("trees", [&] {
        v.boolean({"enabled", "--no-trees", "No trees, mapped or filled in"}, d.trees.enabled);
        v.number({"seed", "--trees-seed", "Seed of the filled-in trees' places and of every tree's variation"},
                 d.trees.seed, 0u, UINT32_MAX);
        v.number({"forest_density", "--trees-forest-density", "Trees per hectare filled into forests and woods"},
                 d.trees.forestDensity, 0.0f, 5000.0f);
        v.number({"park_density", "--trees-park-density", "Trees per hectare filled into parks and gardens"},
                 d.trees.parkDensity, 0.0f, 5000.0f);
        v.number({"scrub_density", "--trees-scrub-density", "Bushes per hectare filled into scrub and heath"},
                 d.trees.scrubDensity, 0.0f, 5000.0f);
        v.number({"outer_forest", "--trees-outer-forest", "Metres of forest in a ring around the city (0: none)"},
                 d.trees.outerForest, 0.0f, 30000.0f);
        v.number({"outer_forest_cell", "--trees-outer-forest-cell", "Metres: the side of the outer forest's cells"},
                 d.trees.outerForestCell, 1.0f, 100.0f);
        v.number({"outer_forest_density", "--trees-outer-forest-density", "Trees per hectare in the outer forest"},
                 d.trees.outerForestDensity, 0.0f, 10000.0f);
        v.number({"clearance", "--trees-clearance", "Metres from a filled tree's trunk to buildings, water and roads"},
                 d.trees.clearance, 0.0f, 50.0f);
        v.number({"default_height", "--trees-default-height", "Metres, of a filled-in tree"}, d.trees.defaultHeight, 1.0f,
                 150.0f);
        v.number({"size_variation", "--trees-size-variation", "Share by which untagged heights and crowns vary"},
                 d.trees.sizeVariation, 0.0f, 0.9f);
        v.number({"conifer_share", "--trees-conifer-share", "Share of conifers among forest trees of unknown leaf type"},
                 d.trees.coniferShare, 0.0f, 1.0f);
        v.number({"roughness", "--trees-roughness", "The crown's noise, as a share of its radius"}, d.trees.roughness,
                 0.0f, 1.0f);
        v.number({"lumps", "--trees-lumps", "The crown noise's lumps per crown radius"}, d.trees.lumps, 0.1f, 10.0f);
        v.choice({"season", "--trees-season", "summer or autumn (deciduous broadleaves take the autumn albedo)"},
                 d.trees.season, kTreeSeasons);
        v.vec3({"bark_albedo", "--trees-bark-albedo", "R,G,B of trunks and branches"}, d.trees.barkAlbedo, 0.0f, 1.0f);
        v.vec3({"leaf_albedo", "--trees-leaf-albedo", "R,G,B of broadleaves in summer"}, d.trees.leafAlbedo, 0.0f, 1.0f);
        v.vec3({"needle_albedo", "--trees-needle-albedo", "R,G,B of conifers"}, d.trees.needleAlbedo, 0.0f, 1.0f);
        v.vec3({"autumn_albedo", "--trees-autumn-albedo", "R,G,B of deciduous broadleaves in autumn"}, d.trees.autumnAlbedo,
               0.0f, 1.0f);
    });
    v.object("photons", [&] {
        v.number({"per_pass", "--photons", "Photons per pass of the photon integrators (one pass per sample)"},
                 d.photons.perPass, 1u, 1u << 26);
        v.number({"radius", "--photon-radius", "Metres: the photon map's gather radius at the first pass"},
                 d.photons.radius, 1e-3f, 1e3f);
        v.number({"alpha", "--photon-alpha", "The photon map's radius reduction (Knaus and Zwicker 2011)"},
                 d.photons.alpha, 0.01f, 1.0f);
        v.number({"texel", "--photon-texel", "Metres: a photon buffer's texel at level 0"}, d.photons.texel, 0.01f, 100.0f);
        v.number({"level_distance", "--photon-level-distance", "Metres: the distance of photon buffer level 0"},
                 d.photons.levelDistance, 0.1f, 1e5f);
    });
    v.optionalObject({"planet", "--planet", "A whole planet instead of the city"}, d.planet, [&](auto& p) {
        v.number({"radius_km", "--planet", "Radius of the base sphere, km"}, p.radiusKm, 10.0, 1e6);
        v.number({"sea_level", "--planet-sea-level", "Metres above the base sphere; within the amplitude"}, p.seaLevel,
                 -1e5f, 1e5f);
        v.number({"amplitude", "--planet-amplitude", "Metres: the terrain's heights lie within +- this"}, p.amplitude, 0.0f,
                 1e5f);
        v.number({"wavelength_km", "--planet-wavelength-km", "Km: wavelength of the fBm's first octave"}, p.wavelengthKm,
                 0.01f, 1e6f);
        v.number({"gain", "--planet-gain", "Amplitude ratio of successive octaves"}, p.gain, 0.05f, 0.95f);
        v.number({"octaves", "--planet-octaves", "Octaves of the fBm"}, p.octaves, 1u, 24u);
        v.number({"seed", "--planet-seed", "Seed of the heightfield's noise"}, p.seed, 0u, UINT32_MAX);
        v.vec3({"ocean_colour", "--planet-ocean-colour", "R,G,B diffuse albedo of the sea"}, p.oceanColour, 0.0f, 1.0f);
        v.number({"atmosphere_scale", "--planet-atmosphere-scale", "The atmosphere's thickness over Earth's 100 km"},
                 p.atmosphereScale, 0.001f, 100.0f);
        v.object("camera", [&] {
            v.number({"altitude_km", "--camera-orbit", "Km above the ground under the camera", Restart}, p.camera.altitudeKm,
                     0.0, 1e6);
            v.number({"lat", "--camera-orbit", "Latitude of the point under the camera", Restart}, p.camera.lat, -90.0, 90.0);
            v.number({"lon", "--camera-orbit", "Longitude of the point under the camera", Restart}, p.camera.lon, -360.0,
                     360.0);
            v.number({"heading", "--camera-orbit", "Degrees clockwise from north", Restart}, p.camera.heading, -360.0f,
                     360.0f);
            v.number({"pitch", "--camera-orbit", "Degrees above the horizon (-90: straight down)", Restart}, p.camera.pitch,
                     -90.0f, 90.0f);
        });
    });
    v.object("clouds", [&] {
        auto& c = d.clouds.layer;
        v.number({"coverage", "--clouds",
                  "Cloud coverage, 0 (none) to 1 (overcast)"},
                 c.coverage, 0.0f, 1.0f);
        v.choice({"type", "--clouds-type", "cumulus (heaps), stratus (sheets) or uniform (a slab: fog)"}, d.clouds.type,
                 kCloudTypes);
        v.number({"altitude", "--clouds-altitude", "Metres of the layer's bottom above y = 0"}, c.bottom, -500.0f, 20000.0f);
        v.number({"thickness", "--clouds-thickness", "Metres from the layer's bottom to its top"}, c.thickness, 10.0f,
                 20000.0f);
        v.number({"density", "--clouds-density", "Extinction per metre where the clouds are densest"}, c.density, 1e-6f,
                 10.0f);
        v.number({"albedo", "--clouds-albedo", "Single-scattering albedo"}, c.albedo, 0.0f, 1.0f);
        v.number({"scale", "--clouds-scale", "Metres of one period of the shape noise"}, c.scale, 100.0f, 1e6f);
        v.number({"radius", "--clouds-radius", "Metres from the origin over which the layer fades out"}, c.radius, 100.0f,
                 1e7f);
        v.vec3({"wind", "--clouds-wind", "X,Y,Z metres the clouds have drifted"}, c.wind, -1e7f, 1e7f);
        v.number({"seed", "--clouds-seed", "Seed of the noise and the weather"}, c.seed, 0u, UINT32_MAX);
        v.number({"phase_forward", "--clouds-phase-forward", "Henyey-Greenstein g of the forward lobe"}, c.forwardG, 0.0f,
                 0.99f);
        v.number({"phase_backward", "--clouds-phase-backward", "g of the backward lobe"}, c.backwardG, -0.99f, 0.0f);
        v.number({"phase_blend", "--clouds-phase-blend", "The forward lobe's weight"}, c.forwardWeight, 0.0f, 1.0f);
        v.number({"octaves", "--clouds-octaves", "Multiple-scattering octaves at a path's last vertex (1: none)"},
                 c.octaves, 1u, kCloudMaxOctaves);
        v.number({"octave_scattering", "--clouds-octave-scattering", "a: octave i scatters a^i of the light"},
                 c.octaveScattering, 0.0f, 1.0f);
        v.number({"octave_extinction", "--clouds-octave-extinction", "b: octave i sees b^i of the extinction"},
                 c.octaveExtinction, 0.0f, 1.0f);
        v.number({"octave_anisotropy", "--clouds-octave-anisotropy", "c: octave i has c^i of the phase's anisotropy"},
                 c.octaveAnisotropy, 0.0f, 1.0f);
    });
    v.object("animation", [&] { visitAnimationFields(d.animation, v); });
}

} // namespace urbis
