#include "app/terrain_accuracy.h"

#include "geometry/scene_intersect.h"
#include "gpu/gpu_backend.h"
#include "io/atomic_file.h"
#include "scene/camera.h"
#include "scene/scene.h"
#include "terrain/terrain_build.h"

#include <nlohmann/json.hpp>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace urbis {
namespace {

double medianOf(std::vector<float> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    const size_t m = v.size() / 2;
    return v.size() % 2 ? v[m] : 0.5 * (double(v[m - 1]) + double(v[m]));
}

/// The camera of `d`, or the default view over the terrain `t`.
Camera accuracyCamera(const SceneDescription& d, const TerrainField& t) {
    const float aspect = float(d.film.width) / float(d.film.height);
    if (d.camera.position && d.camera.target) return makeLookAtCamera(*d.camera.position, *d.camera.target, d.camera.fov, aspect);
    const Bounds3f box = primBounds(t.record);
    const float x = box.centre().x, z = box.lo.z + 0.2f * box.extent().z;
    const float reach = std::min(1000.0f, 0.6f * box.extent().z);
    const Vec3f position{x, t.heightAt(x, z) + 120.0f, z};
    const Vec3f target{x, t.heightAt(x, z + reach), z + reach};
    return makeLookAtCamera(position, target, d.camera.fov, aspect);
}

/// Hit distances (-1: none) and kernel or wall times of `rays` against the terrain alone marched by `march`.
void traceMarch(TerrainField field, TerrainMarch march, const std::vector<Ray>& rays, bool onGpu, int warmup, int repeats,
                std::vector<float>& t, std::vector<float>& ms) {
    field.record.march = march;
    const Scene scene = Scene::build({.materials = terrainMaterials(), .terrain = field});
    t.assign(rays.size(), -1.0f);
    if (onGpu) {
        std::unique_ptr<GpuScene> gpu = GpuScene::upload(scene, rays.size() * (sizeof(Ray) + sizeof(SurfaceHit)));
        const std::vector<SurfaceHit> hits = gpu->intersect(rays);
        for (size_t i = 0; i < rays.size(); ++i)
            if (hits[i].valid()) t[i] = hits[i].t;
        ms = gpu->timeTrace(rays, false, warmup, repeats);
        return;
    }
    const SceneView view = scene.view();
    ms.clear();
    for (int r = 0; r < repeats; ++r) {
        const auto t0 = std::chrono::steady_clock::now();
        tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), 256), [&](const tbb::blocked_range<size_t>& range) {
            for (size_t i = range.begin(); i < range.end(); ++i) {
                const SurfaceHit hit = intersectScene(view, rays[i]);
                t[i] = hit.valid() ? hit.t : -1.0f;
            }
        });
        ms.push_back(float(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count()));
    }
}

} // namespace

void runTerrainAccuracy(const BenchOptions& o, bool onGpu, const std::string& deviceName, int repeats) {
    const SceneDescription& d = o.render.scene;
    TerrainParams params = d.terrain;
    if (!params.enabled()) params.kind = "fbm";
    const TerrainField field = buildTerrain(params, GeoOrigin{}, 0.0f, 0.0f, 0);
    const Camera camera = accuracyCamera(d, field);
    const uint32_t w = d.film.width, h = d.film.height;
    std::vector<Ray> rays(size_t(w) * h);
    for (size_t i = 0; i < rays.size(); ++i)
        rays[i] = camera.generateRay((float(i % w) + 0.5f) / float(w), (float(i / w) + 0.5f) / float(h));

    std::vector<float> reference, referenceMs;
    traceMarch(field, TerrainMarch::Reference, rays, onGpu, 0, 1, reference, referenceMs);
    const TerrainRecord& r = field.record;
    nlohmann::json json = {{"device", onGpu ? "cuda" : "cpu"}, {"device_name", deviceName}, {"width", w}, {"height", h},
                           {"repeats", repeats},
                           {"terrain", {{"samples_x", r.nx}, {"samples_z", r.nz}, {"cell_m", r.cell},
                                        {"height_min_m", r.yMin}, {"height_max_m", r.yMax}}},
                           {"reference", {{"step_m", r.referenceStep}, {"ms", referenceMs}}},
                           {"lei", {{"a", r.leiA}, {"b", r.leiB}, {"c", r.leiC}, {"bisections", r.leiBisections}}}};
    std::printf("urbis bench --terrain-accuracy: %ux%u samples, %.2f m apart; %ux%u rays; %s (%s)\n", r.nx, r.nz, r.cell,
                w, h, deviceName.c_str(), onGpu ? "cuda" : "cpu");
    std::printf("%-10s %8s %8s %8s %12s %12s %12s %11s\n", "march", "hits", "missed", "extra", "mean HDE m", "max HDE m",
                "mean IDE m", "median ms");
    for (const TerrainMarch march : {TerrainMarch::Hierarchy, TerrainMarch::Lei}) {
        std::vector<float> t, ms;
        traceMarch(field, march, rays, onGpu, o.warmup, repeats, t, ms);
        const MarchAccuracy a = marchAccuracy(r, field.data.data(), rays, t, reference);
        const char* name = nameOfChoice(kTerrainMarches, march);
        std::printf("%-10s %8zu %8zu %8zu %12.3g %12.3g %12.3g %11.3f\n", name, a.hits, a.missed, a.extra, a.meanHde,
                    a.maxHde, a.meanIde, medianOf(ms));
        json["methods"][name] = {{"hits", a.hits}, {"missed_intersections", a.missed}, {"extra_intersections", a.extra},
                                 {"mean_hde_m", a.meanHde}, {"max_hde_m", a.maxHde}, {"mean_ide_m", a.meanIde},
                                 {"max_ide_m", a.maxIde}, {"median_ms", medianOf(ms)}, {"ms", ms}};
        for (const HdeBand& band : a.byDistance) {
            std::printf("%-10s   hits %.0f-%s m away: %zu, mean HDE %.3g m, max %.3g m\n", "", band.from,
                        std::isfinite(band.to) ? std::to_string(int(band.to)).c_str() : "", band.hits, band.meanHde, band.maxHde);
            json["methods"][name]["hde_by_distance"].push_back(
                {{"from_m", band.from}, {"to_m", std::isfinite(band.to) ? nlohmann::json(band.to) : nlohmann::json()},
                 {"hits", band.hits}, {"mean_hde_m", band.meanHde}, {"max_hde_m", band.maxHde}});
        }
    }
    if (!o.jsonFile.empty()) writeTextFileAtomically(o.jsonFile, json.dump(2) + "\n");
}

} // namespace urbis
