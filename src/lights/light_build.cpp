#include "lights/light_build.h"

#include "lights/lamp_light.h"
#include "lights/light_bvh_build.h"
#include "lights/sky_light.h"
#include "lights/sun_light.h"
#include "lights/window_light.h"
#include "media/atmosphere_build.h"
#include "scene/lamp_emission.h"
#include "scene/lamp_pieces.h"

#include <cmath>

#include <tbb/parallel_for.h>

namespace urbis {

namespace {

/// The light arrays of scene_arrays.h and their LightListInfo, as buildLights makes them.
struct BuiltLights {
    std::vector<LightRecord> records;
    std::vector<float> powerTable;          ///< buildPiecewiseConstant1D over records' power
    std::vector<EmissiveSurface> surfaces;
    std::vector<TriangleLight> triangles;
    std::vector<EmitterTriangle> emitters;
    std::vector<LampEmitter> lampLights;
    std::vector<float> skyTable;            ///< buildPiecewiseConstant2D over the sky
    LightListInfo info;
};

/// Radius of a sphere around everything the scene holds (1 m for an empty scene): the infinite
/// lights' power is their radiance through a disk of that radius (pbrt-v4 DistantLight::Phi).
float sceneRadius(const Scene& scene) {
    Bounds3f bounds;
    for (const Triangle& t : scene.triangles) bounds.extend(primBounds(t));
    for (const WallRecord& wall : scene.walls) bounds.extend(primBounds(wall));
    return bounds.empty() ? 1.0f : fmaxf(1.0f, 0.5f * length(bounds.extent()));
}

/// Materials that some primitive other than a triangle can show: their emission is not light-sampled.
std::vector<bool> materialsOutsideTriangles(const Scene& scene) {
    std::vector<bool> outside(scene.materials.size(), false);
    auto mark = [&](uint32_t m) {
        if (m < outside.size()) outside[m] = true;
    };
    for (const WallRecord& wall : scene.walls) {
        mark(wall.wallMaterial);
        for (uint32_t i = 0; i < uint32_t(FacadeMaterial::Count); ++i) mark(wall.facadeMaterials + i);
    }
    for (const GroundRecord& ground : scene.grounds) mark(ground.material);
    return outside;
}

/// The sky's luminance table over the equal-area map (lights/sky_light.h: every cell the same solid
/// angle), and its integral over the sphere (luminance per solid angle). With `upperOnly` (an
/// infinite ground plane hides every direction below the horizon from every point above it) the
/// rows below the horizon stay zero. With `compensate`, the table holds only what exceeds the sky's
/// mean luminance (MIS compensation, Karlik et al. 2019; pbrt-v4 ImageInfiniteLight): BSDF sampling
/// already finds the even part well, so light samples go where the sky is brighter than that.
/// Directions of pdf 0 are BSDF sampling's alone, with weight 1: every estimate stays unbiased.
std::vector<float> skyLuminanceTable(const SceneView& scene, uint32_t nu, uint32_t nv, bool upperOnly, bool compensate,
                                     double& integral) {
    std::vector<float> func(size_t(nu) * nv, 0.0f);
    const double cell = 4.0 * kPi / (double(nu) * nv);
    const uint32_t rows = upperOnly ? (nv + 1) / 2 : nv;
    double sum = 0;
    for (uint32_t v = 0; v < rows; ++v)
        for (uint32_t u = 0; u < nu; ++u) {
            const Vec2f uv{(float(u) + 0.5f) / float(nu), (float(v) + 0.5f) / float(nv)};
            const float lum = luminance(skyRadiance(scene, skyDirectionFromUv(uv)));
            func[size_t(v) * nu + u] = lum;
            sum += lum;
        }
    const float mean = compensate ? float(sum / (double(rows) * nu)) : 0.0f;
    integral = 0;
    for (uint32_t v = 0; v < rows; ++v)
        for (uint32_t u = 0; u < nu; ++u) {
            float& f = func[size_t(v) * nu + u];
            f = fmaxf(0.0f, f - mean);
            integral += double(f) * cell;
        }
    return func;
}

/// One light per emitting triangle (in triangle order, so emitterTriangles is sorted): a light of
/// one triangle has bounds the size of a lamp's head or a window, which is what lets the light BVH
/// tell near emitters from far ones (docs/lights.md § Emitting triangles).
void addEmissiveTriangles(const Scene& scene, BuiltLights& lights) {
    const std::vector<bool> outside = materialsOutsideTriangles(scene);
    for (uint32_t i = 0; i < scene.triangles.size(); ++i) {
        const uint32_t m = scene.triangleInfo[i].material;
        if (m >= scene.materials.size() || outside[m] || !(maxComponent(scene.materials[m].emission) > 0.0f)) continue;
        const Triangle& t = scene.triangles[i];
        const double area = 0.5 * double(length(cross(t.p1 - t.p0, t.p2 - t.p0)));
        if (!(area > 0)) continue;
        const Vec3f emission = scene.materials[m].emission;
        const uint32_t light = uint32_t(lights.records.size());
        lights.emitters.push_back({i, light});
        // Flux of a two-sided Lambertian emitter: 2 pi A L.
        lights.records.push_back({LightKind::EmissiveSurface, uint32_t(lights.surfaces.size()),
                                  float(2.0 * kPi * area * luminance(emission))});
        lights.surfaces.push_back({emission, uint32_t(lights.triangles.size()), 1, float(area)});
        lights.triangles.push_back(TriangleLight{t.p0, t.p1, t.p2, 1.0f});
    }
}

/// Lamp `lamp` as a light: a point at its glass's centre whose profile (lights/lamp_light.h) carries
/// its luminous flux in the renderer's units (kLuxPerUnit) in its blackbody's colour.
LampEmitter lampEmitterOf(const LampRecord& lamp) {
    const LampPiece glass = lampPiece(lamp, 3);
    LampEmitter light;
    light.shape = lamp.shape;
    Vec3f centre = glass.a;
    if (glass.shape == LampPieceShape::Sphere) {
        light.glassRadius = light.clearance = glass.b.x;
    } else if (glass.b.x > 0.0f) {   // a lantern's glass: a frustum up from its bottom
        centre.y += 0.5f * glass.b.x;
        light.glassRadius = glass.b.y + 0.5f * glass.b.z * glass.b.x;
        light.glassHeight = glass.b.x;
        light.clearance = std::hypot(glass.highRadius(), 0.5f * glass.b.x);
    } else {                         // a disc facing down: the shadow ray stops a centimetre short
        light.glassRadius = glass.b.y;
        light.clearance = 0.01f;
    }
    light.position = lamp.worldFromLamp(centre);
    light.intensity = blackbodyRgb(lamp.colourTemperature) * (lamp.luminousFlux / kLuxPerUnit / lampProfileIntegral(lamp.shape));
    return light;
}

/// The street lamps (one Point light each, in the order of scene.lamps) and every wall record's lit
/// windows (one Aggregate each, in the order of scene.walls), with their flux as power and their
/// count of lit cells, which the wall's sampler picks among.
void addNightLights(const Scene& scene, const LightBuildOptions& options, BuiltLights& lights) {
    if (options.lamps && !scene.lamps.empty()) {
        lights.info.firstLampLight = uint32_t(lights.records.size());
        for (uint32_t i = 0; i < scene.lamps.size(); ++i) {
            lights.lampLights.push_back(lampEmitterOf(scene.lamps[i]));
            lights.records.push_back({LightKind::Point, i, scene.lamps[i].luminousFlux / kLuxPerUnit});
        }
    }
    if (options.windows && !scene.walls.empty()) {
        lights.info.firstWallLight = uint32_t(lights.records.size());
        std::vector<WallWindowsTotals> totals(scene.walls.size());
        tbb::parallel_for(size_t(0), scene.walls.size(), [&](size_t i) {
            const WallRecord& wall = scene.walls[i];
            totals[i] = wallWindowsTotals(wall, scene.materials[wall.facadeMaterials + uint32_t(FacadeMaterial::RoomLit)].emission);
        });
        for (uint32_t i = 0; i < scene.walls.size(); ++i)
            lights.records.push_back({LightKind::Aggregate, i, totals[i].power, totals[i].litCells});
    }
}

/// LightBounds of an emitting surface: its triangles' box and the cone of their normals, emitting
/// over the hemisphere (theta_e = pi / 2) of both sides.
LightBounds emissiveSurfaceBounds(const Scene& scene, const EmissiveSurface& surface, float power) {
    LightBounds out;
    for (uint32_t i = 0; i < surface.triangleCount; ++i) {
        const TriangleLight& t = scene.triangleLights[surface.firstTriangle + i];
        LightBounds one;
        one.bounds.extend(t.p0);
        one.bounds.extend(t.p1);
        one.bounds.extend(t.p2);
        one.axis = normalize(cross(t.p1 - t.p0, t.p2 - t.p0));
        one.cosThetaO = 1;
        one.cosThetaE = 0;
        one.twoSided = true;
        one.phi = 1;  // any non-zero power: the union only needs the geometry
        out = unionLightBounds(out, one);
    }
    out.phi = power;
    return out;
}

} // namespace

void buildLights(Scene& scene, const LightBuildOptions& options) {
    if (scene.sky.model == SkyModel::Atmosphere && scene.skyViewLut.empty()) buildAtmosphere(scene);
    BuiltLights lights;
    const double radius = sceneRadius(scene);
    const double disk = double(kPi) * radius * radius;
    // The sun and the moon: a disk's power is its radiance times its solid angle through `disk`. A
    // disk wholly below the horizon of an infinite ground lights nothing above it: it leaves the
    // list, where its power would take nearly every light sample from the night's lamps and windows.
    const auto addDisk = [&](const Sun& light, LightKind kind, uint32_t& place) {
        const float sinHalfAngle = std::sqrt(std::fmax(0.0f, 1.0f - light.cosHalfAngle * light.cosHalfAngle));
        if (!scene.grounds.empty() && light.direction.y < -sinHalfAngle) return;
        place = uint32_t(lights.records.size());
        lights.records.push_back({kind, 0, float(disk * luminance(light.radiance) / double(sunPdf(light)))});
    };
    if (options.sun && sunEnabled(scene.sun)) addDisk(scene.sun, LightKind::Sun, lights.info.sunLight);
    if (options.sky && options.skyWidth > 0 && options.skyHeight > 0) {
        double integral = 0;
        std::vector<float> func =
            skyLuminanceTable(scene.view(), options.skyWidth, options.skyHeight, !scene.grounds.empty(), options.compensateSky, integral);
        // Under a bright sun a sky sample takes the place of a sun sample, whose shadows make most of
        // the noise, and its shadow ray is incoherent: the sky is then BSDF sampling's alone (counted
        // in full, unbiased), as it is where the table is empty (docs/lights.md § The light set).
        const double skyPower = disk * integral;
        const double sunPower = lights.records.empty() ? 0.0 : double(lights.records.front().power);
        if (integral > 0 && skyPower >= double(options.skyMinShare) * (skyPower + sunPower)) {
            lights.skyTable = buildPiecewiseConstant2D(func, options.skyWidth, options.skyHeight);
            lights.info.skyNu = options.skyWidth;
            lights.info.skyNv = options.skyHeight;
            lights.info.skyLight = uint32_t(lights.records.size());
            lights.records.push_back({LightKind::Sky, 0, float(skyPower)});
        }
    }
    if (options.moon && sunEnabled(scene.night.moon)) addDisk(scene.night.moon, LightKind::Moon, lights.info.moonLight);
    if (options.surfaces) addEmissiveTriangles(scene, lights);
    if (scene.sun.direction.y < std::sin(options.nightBelowElevation * kPi / 180.0f) || !sunEnabled(scene.sun))
        addNightLights(scene, options, lights);
    std::vector<float> power;
    for (const LightRecord& light : lights.records) power.push_back(light.power);
    lights.powerTable = buildPiecewiseConstant1D(power);
    lights.info.powerIntegral = lights.powerTable.empty() ? 0.0f : lights.powerTable.back();
    lights.info.colliderRadius = options.colliderRadius;
    lights.info.built = true;
    scene.lightRecords = std::move(lights.records);
    scene.lightPower = std::move(lights.powerTable);
    scene.emissiveSurfaces = std::move(lights.surfaces);
    scene.triangleLights = std::move(lights.triangles);
    scene.emitterTriangles = std::move(lights.emitters);
    scene.lampLights = std::move(lights.lampLights);
    scene.skyTable = std::move(lights.skyTable);
    scene.lights = lights.info;
    // The light BVH over every light of finite extent; the infinite ones are sampled apart.
    std::vector<LightBounds> bounds;
    scene.infiniteLights.clear();
    for (uint32_t i = 0; i < scene.lightRecords.size(); ++i) {
        bounds.push_back(lightBoundsOf(scene, scene.lightRecords[i]));
        const LightKind kind = scene.lightRecords[i].kind;
        if (kind == LightKind::Sun || kind == LightKind::Sky || kind == LightKind::Moon) scene.infiniteLights.push_back(i);
    }
    LightBvh bvh = buildLightBvh(bounds);
    scene.lightBvhNodes = std::move(bvh.nodes);
    scene.lightBvhTrails = std::move(bvh.trails);
}

LightBounds lightBoundsOf(const Scene& scene, const LightRecord& light) {
    switch (light.kind) {
    case LightKind::EmissiveSurface: return emissiveSurfaceBounds(scene, scene.emissiveSurfaces[light.index], light.power);
    case LightKind::Point: return lampLightBounds(scene.lampLights[light.index], light.power);
    case LightKind::Aggregate: return wallWindowsLightBounds(scene.walls[light.index], light.power);
    case LightKind::Sun:  // infinite: sampled apart from the tree
    case LightKind::Sky:
    case LightKind::Moon:
    case LightKind::Spot:  // reserved
        break;
    }
    return LightBounds{};
}

} // namespace urbis
