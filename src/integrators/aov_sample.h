// The AOV pass (host+device): the camera ray of each sample traced to its first surface, for the
// film's albedo, normal, position, depth and ids. A pass of its own, run only when the output keeps
// AOVs (EXR), so that the path tracer and its GPU kernel stay as they are.
#pragma once

#include "film/film_view.h"
#include "geometry/scene_intersect.h"
#include "integrators/camera_sample.h"
#include "scene/camera.h"
#include "scene/render_settings.h"
#include "scene/surface_part.h"

namespace urbis {

/// What camera ray `ray` sees first: material albedo and emission, the normal facing the camera,
/// world position, and depth as the distance along the camera's view axis (z depth, not the ray's t).
/// The sky gives zeros and `surface` false.
URBIS_HD inline AovSample aovOfCameraRay(const SceneView& scene, const Camera& camera, const Ray& ray) {
    const SurfaceHit hit = intersectScene(scene, ray);
    AovSample out;
    if (!hit.valid()) return out;
    out.surface = true;
    out.albedo = scene.materials[hit.material].albedo;
    // The emission a camera ray counts in full (the path tracer's weight 1 at its first hit).
    out.emission = scene.materials[hit.material].emission;
    out.normal = hit.normal;
    out.position = hit.position;
    out.depth = hit.t * dot(ray.dir, camera.forward);
    return out;
}

/// Object and part of a surface; kSkyId for both where nothing was hit.
struct SurfaceIds {
    uint32_t object = kSkyId, part = kSkyId;
};

/// The ids of the first surface through the centre of pixel (px, py): the same for both
/// representations of a wall, and for every seed.
URBIS_HD inline SurfaceIds pixelCentreIds(const SceneView& scene, const Camera& camera, const RenderSettings& settings,
                                          uint32_t px, uint32_t py) {
    const Ray ray = camera.generateRay((float(px) + 0.5f) / float(settings.width), (float(py) + 0.5f) / float(settings.height));
    const SurfaceHit hit = intersectScene(scene, ray);
    if (!hit.valid()) return {};
    return {hit.object, uint32_t(hit.part)};
}

/// pixelCentreIds packed into one word, (object << kSurfacePartBits) | part; kSkyId for the sky.
URBIS_HD inline uint32_t primaryHitId(const SceneView& scene, const Camera& camera, const RenderSettings& settings,
                                      uint32_t px, uint32_t py) {
    const SurfaceIds ids = pixelCentreIds(scene, camera, settings, px, py);
    return ids.object == kSkyId ? kSkyId : (ids.object << kSurfacePartBits) | ids.part;
}

/// The AOV pass of pixel (px, py): adds the AOVs of `samples` to a film that keeps them, in sample
/// order; the call that adds sample 0 also sets the pixel's ids.
URBIS_HD inline void addAovSamples(const SceneView& scene, const Camera& camera, const RenderSettings& settings,
                                   uint32_t px, uint32_t py, SampleRange samples, const FilmView& film) {
    const size_t pixel = film.pixel(px, py);
    for (uint32_t s = samples.first; s < samples.first + samples.count; ++s) {
        SampleStream rng = pixelSampleStream(settings, px, py, s);
        addAovSample(film, pixel, aovOfCameraRay(scene, camera, cameraSampleRay(camera, settings, px, py, rng)));
    }
    if (samples.first == 0 && samples.count > 0) {
        const SurfaceIds ids = pixelCentreIds(scene, camera, settings, px, py);
        film.objectId[pixel] = ids.object;
        film.partId[pixel] = ids.part;
    }
}

} // namespace urbis
