#include "lights/light_build.h"

#include "lights/light.h"
#include "media/atmosphere_build.h"

#include <cmath>

#include <tbb/parallel_for.h>

namespace urbis {

uint32_t LightListBuilder::add(uint32_t kind, uint32_t index, float power, uint32_t litCells) {
    const uint32_t place = uint32_t(scene.lightRecords.size());
    if (scene.lights.firstOfKind[kind] == kNoLight) scene.lights.firstOfKind[kind] = place;
    scene.lightRecords.push_back({kind, index, power, litCells});
    return place;
}

void LightListBuilder::parallelFor(size_t n, const std::function<void(size_t)>& f) const {
    tbb::parallel_for(size_t(0), n, f);
}

void buildLights(Scene& scene, const LightBuildOptions& options) {
    if (scene.sky.model == SkyModel::Atmosphere && scene.skyViewLut.empty()) buildAtmosphere(scene);
#define URBIS_CLEAR_LIGHT_ARRAY(Type, name, key) scene.name.clear();
    URBIS_LIGHT_ARRAYS(URBIS_CLEAR_LIGHT_ARRAY)
#undef URBIS_CLEAR_LIGHT_ARRAY
    scene.lights = LightListInfo{};
    LightListBuilder builder{scene, options, lightSceneSphere(scene).radius};
    builder.night = scene.sun.direction.y < std::sin(options.nightBelowElevation * kPi / 180.0f) || !sunEnabled(scene.sun);
    forEachLightKind([&](auto kind) { decltype(kind)::Light::addLights(builder); });
    std::vector<float> power;
    for (const LightRecord& light : scene.lightRecords) power.push_back(light.power);
    scene.lightPower = buildPiecewiseConstant1D(power);
    scene.lights.powerIntegral = scene.lightPower.empty() ? 0.0f : scene.lightPower.back();
    scene.lights.colliderRadius = options.colliderRadius;
    scene.lights.built = true;
    // The light BVH over every light of finite extent; the infinite ones are sampled apart.
    std::vector<LightBounds> bounds;
    for (uint32_t i = 0; i < scene.lightRecords.size(); ++i) {
        bounds.push_back(lightBoundsOf(scene, scene.lightRecords[i]));
        if ((kInfiniteLightKinds >> scene.lightRecords[i].kind) & 1u) scene.infiniteLights.push_back(i);
    }
    LightBvh bvh = buildLightBvh(bounds);
    scene.lightBvhNodes = std::move(bvh.nodes);
    scene.lightBvhTrails = std::move(bvh.trails);
}

LightBounds lightBoundsOf(const Scene& scene, const LightRecord& light) {
    return dispatchLight(light.kind, [&](auto kind) { return decltype(kind)::Light::bounds(scene, light); });
}

} // namespace urbis
