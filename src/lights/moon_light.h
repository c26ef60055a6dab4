// The moon as a light (host+device): a disk of directions as the sun (DiskLightKind), lit by the
// sun's position (scene/night_sky.h; docs/astronomy.md).
#pragma once

#include "lights/sun_light.h"

namespace urbis {

struct MoonLight : DiskLightKind<MoonLight> {
    URBIS_HD static const Sun& disk(const SceneView& scene) { return scene.night.moon; }

    static void addLights(LightListBuilder& b) {
        if (b.options.moon && sunEnabled(b.scene.night.moon)) addDisk(b, b.scene.night.moon);
    }
    /// The disk seen by any ray that meets nothing, the camera's too.
    URBIS_HD static bool escaped(const SceneView& scene, Vec3f, Vec3f dir, uint32_t, Vec3f& radiance) {
        if (!sunContains(scene.night.moon, dir)) return false;
        radiance = scene.night.moon.radiance;
        return true;
    }
};

} // namespace urbis
