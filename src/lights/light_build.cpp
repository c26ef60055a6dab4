#include "lights/light_build.h"

#include "lights/sky_light.h"
#include "lights/sun_light.h"

#include <map>

namespace urbis {

namespace {

/// The light arrays of scene_arrays.h and their LightListInfo, as buildLights makes them.
struct BuiltLights {
    std::vector<LightRecord> records;
    std::vector<float> powerTable;          ///< buildPiecewiseConstant1D over records' power
    std::vector<EmissiveSurface> surfaces;
    std::vector<TriangleLight> triangles;
    std::vector<uint32_t> lightOfMaterial;
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

/// One EmissiveSurface per emitting material of the triangles (in material order).
void addEmissiveSurfaces(const Scene& scene, BuiltLights& lights, float& area) {
    const std::vector<bool> outside = materialsOutsideTriangles(scene);
    std::map<uint32_t, std::vector<uint32_t>> trianglesOf;
    for (uint32_t i = 0; i < scene.triangles.size(); ++i) {
        const uint32_t m = scene.triangleInfo[i].material;
        if (m < scene.materials.size() && !outside[m] && maxComponent(scene.materials[m].emission) > 0.0f)
            trianglesOf[m].push_back(i);
    }
    lights.lightOfMaterial.assign(scene.materials.size(), kNoLight);
    area = 0;
    for (const auto& [material, list] : trianglesOf) {
        EmissiveSurface surface{scene.materials[material].emission, uint32_t(lights.triangles.size()), 0, 0.0f};
        std::vector<double> areas;
        double total = 0;
        for (uint32_t i : list) {
            const Triangle& t = scene.triangles[i];
            const double a = 0.5 * double(length(cross(t.p1 - t.p0, t.p2 - t.p0)));
            if (!(a > 0)) continue;
            areas.push_back(a);
            total += a;
            lights.triangles.push_back(TriangleLight{t.p0, t.p1, t.p2, 0.0f});
        }
        if (areas.empty()) continue;
        double running = 0;
        for (size_t k = 0; k < areas.size(); ++k) {
            running += areas[k];
            lights.triangles[surface.firstTriangle + k].cdf = k + 1 == areas.size() ? 1.0f : float(running / total);
        }
        surface.triangleCount = uint32_t(areas.size());
        surface.area = float(total);
        lights.lightOfMaterial[material] = uint32_t(lights.records.size());
        // Flux of a two-sided Lambertian emitter: 2 pi A L.
        lights.records.push_back({LightKind::EmissiveSurface, uint32_t(lights.surfaces.size()),
                                  float(2.0 * kPi * total * luminance(surface.emission))});
        lights.surfaces.push_back(surface);
        area += surface.area;
    }
}

} // namespace

void buildLights(Scene& scene, const LightBuildOptions& options) {
    BuiltLights lights;
    const double radius = sceneRadius(scene);
    const double disk = double(kPi) * radius * radius;
    if (options.sun && sunEnabled(scene.sun)) {
        lights.info.sunLight = uint32_t(lights.records.size());
        const double solidAngle = 1.0 / double(sunPdf(scene.sun));
        lights.records.push_back({LightKind::Sun, 0, float(disk * luminance(scene.sun.radiance) * solidAngle)});
    }
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
    float area = 0;
    if (options.surfaces) addEmissiveSurfaces(scene, lights, area);
    else lights.lightOfMaterial.assign(scene.materials.size(), kNoLight);
    std::vector<float> power;
    for (const LightRecord& light : lights.records) power.push_back(light.power);
    lights.powerTable = buildPiecewiseConstant1D(power);
    lights.info.powerIntegral = lights.powerTable.empty() ? 0.0f : lights.powerTable.back();
    lights.info.built = true;
    scene.lightRecords = std::move(lights.records);
    scene.lightPower = std::move(lights.powerTable);
    scene.emissiveSurfaces = std::move(lights.surfaces);
    scene.triangleLights = std::move(lights.triangles);
    scene.lightOfMaterial = std::move(lights.lightOfMaterial);
    scene.skyTable = std::move(lights.skyTable);
    scene.lights = lights.info;
}

Bounds3f lightBounds(const Scene& scene, const LightRecord& light) {
    Bounds3f bounds;
    if (light.kind != LightKind::EmissiveSurface) return bounds;
    const EmissiveSurface& surface = scene.emissiveSurfaces[light.index];
    for (uint32_t i = 0; i < surface.triangleCount; ++i) {
        const TriangleLight& t = scene.triangleLights[surface.firstTriangle + i];
        bounds.extend(t.p0);
        bounds.extend(t.p1);
        bounds.extend(t.p2);
    }
    return bounds;
}

} // namespace urbis
