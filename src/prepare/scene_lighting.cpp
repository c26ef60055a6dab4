#include "prepare/scene_lighting.h"

#include "description/celestial_parts.h"
#include "description/scene_parts.h"
#include "lights/light_build.h"
#include "media/atmosphere_build.h"

namespace urbis {

void lightScene(Scene& scene, const SceneDescription& d, const GeoOrigin& origin) {
    const CelestialLights celestial = celestialLightsOf(d, origin);
    const Atmosphere before = scene.sky.atmosphere;   // what the scene's tables, if any, were built for
    scene.sun = celestial.sun;
    scene.night = celestial.night;
    scene.sky = skyOf(d.sky);
    // Takes the sun's transmittance into scene.sun (the sun is set afresh above); a scene lit before
    // keeps the tables that do not depend on the sun.
    buildAtmosphere(scene, true, &before);
    buildLights(scene);
}

void relightWindows(Scene& scene, std::span<const WindowUse> uses, float hour) {
    const uint8_t shop = chanceByte(litShopWindowShare(hour));
    for (WallRecord& wall : scene.walls) {
        if (wall.object == 0 || wall.object > uses.size()) continue;
        wall.litChance = chanceByte(litRoomShare(uses[wall.object - 1], hour));
        wall.shopLitChance = shop;
    }
}

} // namespace urbis
