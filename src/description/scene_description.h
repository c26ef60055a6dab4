// The scene description: every parameter of a render, as plain structs with their defaults. The
// command line and scene files (description/scene_json.h) both produce one; each phase of a render
// reads only its part (import: source; camera framing: camera; render: integrator and film).
// docs/scene_files.md lists every key of its JSON form.
#pragma once

#include "citygen/city_mesher.h"
#include "base/choice.h"
#include "description/animation_description.h"
#include "description/planet_description.h"
#include "scene/geometry_modes.h"
#include "film/film_layers.h"
#include "scene/cloud_layer.h"
#include "scene/integrator_choice.h"
#include "scene/sky.h"
#include "math/vec.h"
#include "terrain/terrain_params.h"
#include "streets/water_options.h"

#include <array>
#include <cstdint>
#include <iterator>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace urbis {

/// The largest film width and height; the memory check (--max-memory) bounds their product.
inline constexpr uint32_t kMaxImageSide = 65536;
/// The most samples per pixel one render takes.
inline constexpr uint32_t kMaxSpp = 1u << 20;
/// The largest generated city: the layout's own limit (layout/city_layout.h), the 10 million buildings
/// that a GPU's memory holds (docs/scale.md § Millions of buildings).
inline constexpr uint64_t kMaxDescribedBuildings = 10'000'000;

/// Where the city comes from: an OSM file, or the generated city.
struct SourceDescription {
    std::string osm;                               ///< OSM file (.osm, .osm.pbf, ...); empty: the generated city
    std::optional<std::array<double, 4>> bbox;     ///< OSM crop, degrees: min lon, min lat, max lon, max lat; none: the file's header box
    /// Metres {min, max}: OSM buildings without height tags get a seeded height in it (none: estimated
    /// from neighbours and a table of types); the generated city's heights (none: the layout's default).
    std::optional<std::array<float, 2>> heightRange;
    float metresPerLevel = 3.0f;                   ///< storey height for building:levels
    float heightScale = 1.0f;                      ///< multiplies every building's heights
    uint64_t buildings = 400;                      ///< size of the generated city
    uint32_t seed = 1;                             ///< of the generated layout and of every building's seed
};

/// A camera placed by geography: at a longitude, latitude and altitude, looking along a heading.
struct GeoCameraDescription {
    double lon = 0, lat = 0;   ///< degrees, WGS84
    float altitude = 100;      ///< metres above the ground plane (y = 0: sea level on a DEM)
    float heading = 0;         ///< degrees clockwise from north
    float pitch = -20;         ///< degrees above the horizon (negative looks down)
    bool aboveGround = false;  ///< altitude above the terrain under the camera instead (`agl`)
};

/// The camera: a position and target in world metres, or a geographic placement (OSM only), or
/// neither: the automatic framing of the whole city.
struct CameraDescription {
    std::optional<Vec3f> position, target;     ///< world metres (x east, y up, z south); both or neither
    std::optional<GeoCameraDescription> geo;   ///< excludes position and target
    float fov = 50.0f;                         ///< vertical field of view, degrees
};

struct SunDescription {
    float elevation = 40.0f;                   ///< degrees above the horizon
    float azimuth = 150.0f;                    ///< degrees clockwise from north
    float angularRadius = 0.27f;               ///< degrees
    /// On a surface facing the sun, in the renderer's relative units: about six times the sky's.
    Vec3f irradiance{3.3f, 3.1f, 2.8f};
};

/// The date, time and place that set the sun, the moon and the stars (docs/astronomy.md).
struct AstronomyDescription {
    /// ISO 8601 with a UTC offset or Z ("2024-06-21T20:30+02:00"); empty: no time (the sun from
    /// SunDescription's angles, no moon, no stars).
    std::string time;
    /// LON, LAT in degrees; none: the OSM extract's centre (the import's projection origin), or
    /// kDefaultLocation for the generated city.
    std::optional<std::array<double, 2>> location;
    /// With a time: the sun's elevation and azimuth come from it; false: from SunDescription (--sun).
    bool sunFromTime = true;
};

/// Where the generated city stands: Prague's Old Town Square (LON, LAT degrees), where the thesis
/// its facades come from was written.
inline constexpr std::array<double, 2> kDefaultLocation{14.4213, 50.0875};

/// The sky (scene/sky.h): Hillaire's atmosphere (docs/atmosphere.md), or the analytic sky, a
/// zenith-to-horizon gradient above a constant ground.
struct SkyDescription {
    Vec3f zenith = Sky{}.zenith;                      ///< analytic
    Vec3f horizon = Sky{}.horizon;                    ///< analytic
    Vec3f ground = Sky{}.ground;                      ///< analytic
    float exponent = Sky{}.exponent;                  ///< analytic
    std::string model = "atmosphere";                 ///< one of kSkyModels
    float aerosols = 1.0f;                            ///< scales the Mie (aerosol) coefficients of Earth's standard atmosphere
    float ozone = 1.0f;                               ///< scales the ozone absorption
    float mieAnisotropy = Atmosphere{}.mieG;          ///< g of the aerosols' phase function
    Vec3f groundAlbedo = Atmosphere{}.groundAlbedo;   ///< of the planet's ground (multiple scattering)
    float altitude = 0.0f;                            ///< metres of the world's y = 0 above sea level
    bool aerialPerspective = true;                    ///< haze along path segments (atmosphere only)
};

/// The night's lights. `hour` (local clock hours, 0 to 24) sets which rooms are lit
/// (citygen/window_schedule.h); negative: from the sun (hourOf in description/scene_parts.h).
struct LightsDescription {
    float hour = -1.0f;
};

/// Materials and style overrides: the city's fixed materials, and wall and roof colours by building
/// type for the buildings whose tags name no colour (the palettes' colours otherwise).
struct MaterialsDescription {
    CityMaterials city;
    std::map<std::string, Vec3f> wallColourByType;   ///< buildingTypeName -> linear colour
    std::map<std::string, Vec3f> roofColourByType;
};

/// How each kind of geometry is represented, and the BVH tiling of procedural walls.
struct GeometryDescription {
    GeometryModes modes;
    std::string wallTiles = "whole";   ///< "whole" or "SLOTSxFLOORS" (wallTileSizeOf)
    bool streets = true;               ///< roads, sidewalks, ground cover, water and lamps; false: buildings on the bare ground
    std::string traffic = "auto";      ///< the side traffic keeps: "auto" (by the city's place), "right" or "left"
};

/// The integrator and its parameters. `lightSampler` picks among the lights ("uniform", "power",
/// "bvh" or "colliders"); `kind` one of kIntegratorKinds.
struct IntegratorDescription {
    std::string kind = "path";
    uint32_t spp = 16;
    uint32_t seed = 1;           ///< of the sampler
    uint32_t maxDepth = 8;       ///< path vertices after the camera
    uint32_t rrDepth = 3;        ///< Russian roulette starts at this depth
    float rrSurvival = 0.95f;    ///< largest survival probability of Russian roulette
    std::string lightSampler = "power";
    uint32_t lightSamples = 1;   ///< light samples per path vertex (0: BSDF sampling alone)
};

/// The photon integrators' parameters (docs/photons.md).
struct PhotonsDescription {
    uint32_t perPass = 65536;      ///< photons traced per pass (one pass per sample)
    float radius = 1.0f;           ///< metres: the photon map's gather radius at the first pass
    float alpha = 0.7f;            ///< the photon map's radius reduction (Knaus and Zwicker 2011)
    float texel = 0.5f;            ///< metres: a photon buffer's texel at level 0
    float levelDistance = 40.0f;   ///< metres: distance of level 0; each doubling one level more (0-4)
};


struct FilmDescription {
    uint32_t width = 1280, height = 720;
    float exposure = -0.6f;            ///< stops
    std::string output = "urbis.png"; ///< the image; its extension picks the format
    /// Layers of kFilmLayerNames (film/film_layers.h) an .exr output holds besides RGBA (a .png holds none).
    std::vector<std::string> layers{std::begin(kFilmLayerNames), std::end(kFilmLayerNames)};
    bool exrFloat = false;             ///< an .exr's colour, albedo and normal as float rather than half
    bool denoise = false;              ///< the AOV-guided denoiser on the HDR film before it is written (docs/film.md)
};

/// The cloud layer (scene/cloud_layer.h, docs/clouds.md): coverage 0 (the default) makes none.
struct CloudsDescription {
    CloudLayer layer;
    std::string type = "cumulus";   ///< one of kCloudTypes
};

struct SceneDescription {
    SourceDescription source;
    CameraDescription camera;
    SunDescription sun;
    AstronomyDescription astronomy;
    SkyDescription sky;
    LightsDescription lights;
    MaterialsDescription materials;
    GeometryDescription geometry;
    IntegratorDescription integrator;
    FilmDescription film;
    TerrainParams terrain;   ///< none by default: the flat ground
    WaterOptions water;   ///< the water's bed and waves (docs/water.md)
    TreeOptions trees;   ///< where trees are filled in, their sizes, crowns and colours (nature/tree_options.h)
    PhotonsDescription photons;
    std::optional<PlanetDescription> planet;  ///< a whole planet instead of the city (docs/planets.md)
    CloudsDescription clouds;
    AnimationDescription animation;   ///< camera and time-of-day keyframes (docs/animation.md)
};

/// The choices of GeometryDescription::traffic: "auto" (none) takes the side of the city's place.
inline constexpr Choice<std::optional<TrafficSide>> kTrafficSides[] = {
    {"auto", std::nullopt}, {"right", TrafficSide::Right}, {"left", TrafficSide::Left}};
/// The choices of SkyDescription::model.
inline constexpr Choice<SkyModel> kSkyModels[] = {{"atmosphere", SkyModel::Atmosphere}, {"analytic", SkyModel::Analytic}};
/// The choices of CloudsDescription::type.
inline constexpr Choice<CloudType> kCloudTypes[] = {
    {"cumulus", CloudType::Cumulus}, {"stratus", CloudType::Stratus}, {"uniform", CloudType::Uniform}};
/// The representations of GeometryModes' kinds.
inline constexpr Choice<Representation> kRepresentations[] = {
    {"procedural", Representation::Procedural}, {"triangles", Representation::Triangles}, {"plain", Representation::Plain}};

} // namespace urbis
