// A Scene's arrays (scene_arrays.h) mirrored in device memory. CUDA-only header (included by .cu
// files alone).
#pragma once

#include "gpu/device_buffer.h"
#include "scene/scene.h"

namespace urbis {

/// The device copies of a Scene's arrays; small records (sun, sky, moon and stars) travel by value in view().
struct DeviceScene {
#define URBIS_DEVICE_MEMBER(Type, name, key) DeviceBuffer<Type> name;
    URBIS_SCENE_ARRAYS(URBIS_DEVICE_MEMBER)
#undef URBIS_DEVICE_MEMBER
    Sun sun;
    Sky sky;
    NightSky night;
    LightListInfo lights;

    /// Device bytes the arrays of `scene` take.
    static size_t bytesFor(const Scene& scene) { return scene.memory().total(); }

    /// Copies every array of `scene` to the device, and its small records by value.
    void upload(const Scene& scene) {
#define URBIS_DEVICE_UPLOAD(Type, name, key) name.upload(scene.name);
        URBIS_SCENE_ARRAYS(URBIS_DEVICE_UPLOAD)
#undef URBIS_DEVICE_UPLOAD
        sun = scene.sun;
        sky = scene.sky;
        night = scene.night;
        lights = scene.lights;
    }

    /// Copies again what the time of day sets (prepare/scene_lighting.h: relightWindows, then
    /// lightScene): the walls' lit chances, the light list and its BVH, the sky's tables and LUTs, and
    /// the small records. The rest (geometry, BVH, terrain, clouds) does not depend on the hour.
    void uploadLighting(const Scene& scene) {
        walls.upload(scene.walls);
#define URBIS_DEVICE_UPLOAD_LIGHT(Type, name, key) name.upload(scene.name);
        URBIS_LIGHT_ARRAYS(URBIS_DEVICE_UPLOAD_LIGHT)
#undef URBIS_DEVICE_UPLOAD_LIGHT
        transmittanceLut.upload(scene.transmittanceLut);
        multiScatteringLut.upload(scene.multiScatteringLut);
        skyViewLut.upload(scene.skyViewLut);
        sun = scene.sun;
        sky = scene.sky;
        night = scene.night;
        lights = scene.lights;
    }

    /// Device bytes held now, by array.
    SceneMemory memory() const {
        SceneMemory out;
#define URBIS_DEVICE_BYTES(Type, name, key) out.name = name.bytes();
        URBIS_SCENE_ARRAYS(URBIS_DEVICE_BYTES)
#undef URBIS_DEVICE_BYTES
        return out;
    }

    /// What kernels read: the same SceneView the CPU backend gets, over device pointers.
    SceneView view() const { return makeSceneView(*this, sun, sky, night, lights); }
};

} // namespace urbis
