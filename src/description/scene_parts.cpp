#include "description/scene_parts.h"

#include "description/building_type_names.h"
#include "description/celestial_parts.h"
#include "base/input_error.h"
#include "osm/geo_projection.h"
#include "scene/camera_framing.h"
#include "scene/scene.h"
#include "scene/terrain_field.h"

#include <cmath>

namespace urbis {

LayoutParams layoutParamsOf(const SourceDescription& source) {
    LayoutParams params;
    params.buildings = source.buildings;
    params.seed = source.seed;
    if (source.heightRange) {
        params.minBuildingHeight = (*source.heightRange)[0];
        params.maxBuildingHeight = (*source.heightRange)[1];
    }
    return params;
}

ImportOptions importOptionsOf(const SourceDescription& source) {
    ImportOptions params;
    params.bbox = source.bbox;
    params.untaggedHeightRange = source.heightRange;
    params.metresPerLevel = source.metresPerLevel;
    params.seed = source.seed;
    return params;
}

void applyColourOverrides(const MaterialsDescription& materials, CityModel& city) {
    if (materials.wallColourByType.empty() && materials.roofColourByType.empty()) return;
    const auto colourOf = [](const std::map<std::string, Vec3f>& byType, BuildingType type, Rgb& colour) {
        auto it = byType.find(buildingTypeName(type));
        if (it != byType.end()) colour = Rgb{it->second.x, it->second.y, it->second.z};
    };
    for (Building& b : city.buildings) {
        if (!b.wallColourTagged) colourOf(materials.wallColourByType, b.type, b.wallColour);
        if (!b.roofColourTagged) colourOf(materials.roofColourByType, b.type, b.roofColour);
    }
}

Sun sunOf(const SunDescription& sun) { return makeSun(sun.elevation, sun.azimuth, sun.angularRadius, sun.irradiance); }

float hourOf(const SceneDescription& d) {
    if (d.lights.hour >= 0.0f) return d.lights.hour;
    if (const std::optional<double> clock = localHourOf(d.astronomy)) return float(*clock);
    if (d.sun.elevation >= 0.0f) return 12.0f;
    const float azimuth = std::fmod(std::fmod(d.sun.azimuth, 360.0f) + 360.0f, 360.0f);
    return azimuth >= 180.0f ? 21.0f : 5.0f;
}

Sky skyOf(const SkyDescription& d) {
    Sky sky;
    sky.zenith = d.zenith;
    sky.horizon = d.horizon;
    sky.ground = d.ground;
    sky.exponent = d.exponent;
    sky.model = choiceNamed(kSkyModels, d.model).value_or(SkyModel::Atmosphere);
    Atmosphere& a = sky.atmosphere;
    a.mieScattering *= d.aerosols;
    a.mieAbsorption *= d.aerosols;
    a.ozoneAbsorption *= d.ozone;
    a.mieG = d.mieAnisotropy;
    a.groundAlbedo = d.groundAlbedo;
    a.altitude = d.altitude * 1e-3f;
    sky.aerialPerspective = d.aerialPerspective;
    return sky;
}

RenderSettings renderSettingsOf(const IntegratorDescription& integrator, const FilmDescription& film) {
    RenderSettings settings;
    settings.width = film.width;
    settings.height = film.height;
    settings.spp = integrator.spp;
    settings.seed = integrator.seed;
    settings.maxDepth = integrator.maxDepth;
    settings.rrDepth = integrator.rrDepth;
    settings.rrSurvival = integrator.rrSurvival;
    settings.lightSampler = choiceNamed(kLightSamplers, integrator.lightSampler).value_or(settings.lightSampler);
    settings.lightSamples = integrator.lightSamples;
    settings.integrator = choiceNamed(kIntegratorKinds, integrator.kind).value_or(settings.integrator);
    return settings;
}

void applyPhotonSettings(const PhotonsDescription& photons, RenderSettings& settings) {
    settings.photonsPerPass = photons.perPass;
    settings.photonRadius = photons.radius;
    settings.photonAlpha = photons.alpha;
    settings.photonTexel = photons.texel;
    settings.photonLevelDistance = photons.levelDistance;
}

RenderSettings renderSettingsOf(const SceneDescription& scene) {
    RenderSettings settings = renderSettingsOf(scene.integrator, scene.film);
    applyPhotonSettings(scene.photons, settings);
    return settings;
}

uint32_t filmLayerMaskOf(const std::vector<std::string>& layers) {
    uint32_t mask = 0;
    for (const std::string& name : layers)
        for (uint32_t i = 0; i < kFilmLayerCount; ++i)
            if (name == kFilmLayerNames[i]) mask |= 1u << i;
    return mask;
}

GroundHeight groundOf(const TerrainField& terrain) {
    if (terrain.empty()) return {};
    return [&terrain](float x, float z) { return terrain.heightAt(x, z); };
}

GroundHeight groundOf(const Scene& scene) {
    if (scene.terrains.empty()) return {};
    return [&scene](float x, float z) { return terrainHeight(scene.terrains[0], scene.terrainData.data(), x, z); };
}

Camera cameraOf(const CameraDescription& camera, float aspect, const GeoOrigin& origin,
                std::span<const Bounds3f> framingPieces, const GroundHeight& groundAt) {
    if (camera.position && camera.target) return makeLookAtCamera(*camera.position, *camera.target, camera.fov, aspect);
    if (camera.geo) {
        if (!origin.valid) throw InputError("--camera-geo (camera.geo): needs a city imported from OSM", FailureKind::Usage);
        const GeoCameraDescription& g = *camera.geo;
        const Vec2d local = GeoProjection(LonLat{origin.lon, origin.lat}).project(LonLat{g.lon, g.lat});
        const float x = float(local.x), z = float(-local.y);
        const float ground = g.aboveGround && groundAt ? groundAt(x, z) : 0.0f;
        return cameraFromHeading(Vec3f{x, g.altitude + ground, z}, g.heading, g.pitch, camera.fov, aspect);
    }
    return frameCity(framingPieces, camera.fov, aspect);
}

CloudLayer cloudLayerOf(const CloudsDescription& clouds) {
    CloudLayer layer = clouds.layer;
    layer.type = choiceNamed(kCloudTypes, clouds.type).value_or(CloudType::Cumulus);
    return layer;
}

} // namespace urbis
