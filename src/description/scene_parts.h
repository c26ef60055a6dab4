// What each phase of a render takes from the scene description: the importer and the layout their
// parameters, the city its style overrides, the scene its lights, the renderer its settings.
#pragma once

#include "description/scene_description.h"
#include "layout/city_layout.h"
#include "scene/sky.h"
#include "scene/sun.h"
#include "math/bounds.h"
#include "model/city_model.h"
#include "osm/import_options.h"
#include "scene/camera.h"
#include "scene/render_settings.h"

#include <functional>
#include <span>

namespace urbis {

/// The generated city's parameters: size, seed, and the height range where one is given.
LayoutParams layoutParamsOf(const SourceDescription& source);

/// The OSM importer's parameters: crop, seed, metres per level, untagged height range.
ImportOptions importOptionsOf(const SourceDescription& source);

/// Sets the wall and roof colours of `city`'s buildings whose tags name none (Building::
/// wallColourTagged, roofColourTagged) from the overrides by building type, where one is given.
void applyColourOverrides(const MaterialsDescription& materials, CityModel& city);

Sun sunOf(const SunDescription& sun);
/// The local hour (0 to 24) that sets which rooms are lit: lights.hour where it is set (not
/// negative); else the local clock hour of astronomy.time where given; else from the sun: 12 while it is up, 21 after it sets in the west (azimuth 180 to
/// 360), 5 before it rises in the east.
float hourOf(const SceneDescription& d);
Sky skyOf(const SkyDescription& sky);
/// The cloud layer the description asks for (its type from the name).
CloudLayer cloudLayerOf(const CloudsDescription& clouds);

/// The per-frame settings of the integrator on a film of that size.
RenderSettings renderSettingsOf(const IntegratorDescription& integrator, const FilmDescription& film);

/// The photon integrators' parameters into `settings`.
void applyPhotonSettings(const PhotonsDescription& photons, RenderSettings& settings);

/// The render settings of `scene`: its integrator's, its film's size and its photon integrators'.
RenderSettings renderSettingsOf(const SceneDescription& scene);

/// The layer mask (film/film_layers.h) of film.layers' names.
uint32_t filmLayerMaskOf(const std::vector<std::string>& layers);

struct Scene;
struct TerrainField;

/// The ground's height (m) at world (x, z): a terrain's, or 0 (the ground plane).
using GroundHeight = std::function<float(float x, float z)>;

/// `terrain`'s height (terrainHeight) where it is not empty, else 0; holds a reference to it.
GroundHeight groundOf(const TerrainField& terrain);

/// The height of `scene`'s terrain (its first), or 0 without one; holds a reference to the scene.
GroundHeight groundOf(const Scene& scene);

/// The camera `camera` describes for an image of `aspect` (width / height): looking from position
/// at target; placed by geography around `origin` (the imported city's; InputError if invalid), its
/// altitude above `groundAt` under it where the placement says aboveGround (none: above y = 0); or
/// else framing the city's `framingPieces` (frameCity).
Camera cameraOf(const CameraDescription& camera, float aspect, const GeoOrigin& origin,
                std::span<const Bounds3f> framingPieces, const GroundHeight& groundAt = {});

} // namespace urbis
