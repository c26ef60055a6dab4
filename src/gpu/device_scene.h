// A Scene's flat arrays mirrored in device memory. CUDA-only header (included by .cu files alone).
#pragma once

#include "gpu/device_buffer.h"
#include "scene/scene.h"

namespace urbis {

/// The device copies of a Scene's arrays; small records (ground, sun, sky) travel by value in view().
struct DeviceScene {
    DeviceBuffer<BvhNode> nodes;
    DeviceBuffer<Triangle> triangles;
    DeviceBuffer<TriangleInfo> triangleInfo;
    DeviceBuffer<uint32_t> primRefs;
    DeviceBuffer<WallRecord> walls;
    DeviceBuffer<Material> materials;
    DeviceBuffer<LightRecord> lightRecords;
    DeviceBuffer<float> lightPower;
    DeviceBuffer<EmissiveSurface> emissiveSurfaces;
    DeviceBuffer<TriangleLight> triangleLights;
    DeviceBuffer<uint32_t> lightOfMaterial;
    DeviceBuffer<float> skyTable;
    SceneLights lights;  ///< the host arrays' sizes and scalars (the view's counts); arrays not used on the device
    GroundPlane ground;
    Sun sun;
    Sky sky;

    /// The one place that pairs each host array of a Scene with its device buffer: new scene
    /// arrays (facade records, lamps, ...) are added here and in view(), nowhere else.
    /// f(const std::vector<T>& host, DeviceBuffer<T>& device) is called for each pair.
    template <typename F>
    void forEachArray(const Scene& scene, F&& f) {
        f(scene.nodes, nodes);
        f(scene.triangles, triangles);
        f(scene.info, triangleInfo);
        f(scene.primRefs, primRefs);
        f(scene.walls, walls);
        f(scene.materials, materials);
        f(scene.lights.records, lightRecords);
        f(scene.lights.powerTable, lightPower);
        f(scene.lights.surfaces, emissiveSurfaces);
        f(scene.lights.triangles, triangleLights);
        f(scene.lights.lightOfMaterial, lightOfMaterial);
        f(scene.lights.skyTable, skyTable);
    }

    /// Device bytes the arrays of `scene` take.
    static size_t bytesFor(const Scene& scene) {
        size_t bytes = 0;
        DeviceScene probe;
        probe.forEachArray(scene, [&](const auto& host, auto&) { bytes += host.size() * sizeof(host[0]); });
        return bytes;
    }

    /// Copies every array of `scene` to the device, and its small records by value.
    void upload(const Scene& scene) {
        forEachArray(scene, [](const auto& host, auto& device) { device.upload(host); });
        ground = scene.ground;
        sun = scene.sun;
        sky = scene.sky;
        lights = scene.lights;
    }

    /// What kernels read: the same SceneView the CPU backend gets, over device pointers.
    SceneView view() const {
        return makeSceneView(nodes, triangles, triangleInfo, primRefs, walls, materials, ground, sun, sky,
                             lights.view(lightRecords, lightPower, emissiveSurfaces, triangleLights, lightOfMaterial, skyTable));
    }
};

} // namespace urbis
