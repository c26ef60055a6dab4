// BVH build speed and closest-hit rays/s of urbis against Embree 3 on the same triangles
// and rays. Run: build/urbis_bench --benchmark_counters_tabular=true
#include "accel/wide_bvh_build.h"
#include "bench_scene.h"
#include "bvh4/build.h"
#include "bvh4/triangle_scene.h"
#include "geometry/wide_triangle_scene.h"
#include "scene/wide_triangle_scene_build.h"
#include "scene/camera_framing.h"

#include <benchmark/benchmark.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#if URBIS_HAVE_EMBREE
#include <embree3/rtcore.h>
#endif

#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <string>
#include <thread>

namespace urbis::bench {
namespace {

/// World bounds of all triangles.
Bounds3f sceneBounds(const std::vector<Triangle>& tris) {
    Bounds3f b;
    for (const Triangle& t : tris) {
        b.extend(t.p0);
        b.extend(t.p1);
        b.extend(t.p2);
    }
    return b;
}

std::vector<Bounds3f> boundsOf(const std::vector<Triangle>& tris) {
    std::vector<Bounds3f> bounds(tris.size());
    tbb::parallel_for(size_t(0), tris.size(), [&](size_t i) {
        bounds[i].extend(tris[i].p0);
        bounds[i].extend(tris[i].p1);
        bounds[i].extend(tris[i].p2);
    });
    return bounds;
}

/// The triangles in a BVH's leaf order.
std::vector<Triangle> inLeafOrder(const std::vector<Triangle>& tris, const std::vector<uint32_t>& primOrder) {
    std::vector<Triangle> sorted(tris.size());
    for (size_t i = 0; i < sorted.size(); ++i) sorted[i] = tris[primOrder[i]];
    return sorted;
}

/// Primary rays of a pinhole camera above the city, looking across it and down.
std::vector<Ray> primaryRays(const Camera& camera, int width, int height) {
    std::vector<Ray> rays;
    rays.reserve(size_t(width) * height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) rays.push_back(camera.generateRay((x + 0.5f) / width, (y + 0.5f) / height));
    return rays;
}

/// Cosine-distributed bounce rays from the primary hits, on the side of the surface the
/// primary ray came from, offset along the normal.
std::vector<Ray> diffuseRays(const TriangleSceneView& view, const std::vector<Ray>& primary) {
    std::mt19937 rng(17);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<Ray> rays;
    for (const Ray& ray : primary) {
        const Hit hit = intersectClosest(view, ray);
        if (!hit.valid()) continue;
        const Triangle& tri = view.triangles[hit.prim];
        Vec3f n = normalize(cross(tri.p1 - tri.p0, tri.p2 - tri.p0));
        if (dot(n, ray.dir) > 0.0f) n = -n;
        const Vec3f t = normalize(std::fabs(n.x) > 0.5f ? cross(n, Vec3f{0, 1, 0}) : cross(n, Vec3f{1, 0, 0}));
        const Vec3f b = cross(n, t);
        const float r = std::sqrt(unit(rng)), phi = 6.2831853f * unit(rng);
        const Vec3f dir = t * (r * std::cos(phi)) + b * (r * std::sin(phi)) + n * std::sqrt(std::fmax(0.0f, 1.0f - r * r));
        const Vec3f p = ray.origin + ray.dir * hit.t;
        rays.push_back({p + n * 1e-3f, dir});
    }
    return rays;
}

#if URBIS_HAVE_EMBREE
/// The same triangles in an Embree 3 scene. RTC_BUILD_QUALITY_HIGH builds an SBVH (spatial
/// splits, the strongest reference); MEDIUM a binned SAH BVH like ours.
struct EmbreeScene {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;

    EmbreeScene(const std::vector<Triangle>& tris, RTCBuildQuality quality) {
        device = rtcNewDevice(nullptr);
        scene = rtcNewScene(device);
        rtcSetSceneBuildQuality(scene, quality);
        RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        rtcSetGeometryBuildQuality(geom, quality);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                              3 * sizeof(float), 3 * tris.size()));
        auto* idx = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                   3 * sizeof(uint32_t), tris.size()));
        for (size_t i = 0; i < tris.size(); ++i) {
            const Vec3f p[3] = {tris[i].p0, tris[i].p1, tris[i].p2};
            for (int k = 0; k < 3; ++k) {
                v[9 * i + 3 * k + 0] = p[k].x;
                v[9 * i + 3 * k + 1] = p[k].y;
                v[9 * i + 3 * k + 2] = p[k].z;
                idx[3 * i + k] = uint32_t(3 * i + k);
            }
        }
        rtcCommitGeometry(geom);
        rtcAttachGeometry(scene, geom);
        rtcReleaseGeometry(geom);
        rtcCommitScene(scene);
    }
    ~EmbreeScene() {
        rtcReleaseScene(scene);
        rtcReleaseDevice(device);
    }
    EmbreeScene(const EmbreeScene&) = delete;
    EmbreeScene& operator=(const EmbreeScene&) = delete;

    /// Closest hit; returns the distance, or a negative value on a miss.
    float intersect(const Ray& ray) const {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRayHit rh;
        rh.ray.org_x = ray.origin.x;
        rh.ray.org_y = ray.origin.y;
        rh.ray.org_z = ray.origin.z;
        rh.ray.dir_x = ray.dir.x;
        rh.ray.dir_y = ray.dir.y;
        rh.ray.dir_z = ray.dir.z;
        rh.ray.tnear = ray.tmin;
        rh.ray.tfar = ray.tmax;
        rh.ray.time = 0.0f;
        rh.ray.mask = 0xffffffffu;
        rh.ray.id = 0;
        rh.ray.flags = 0;
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene, &context, &rh);
        return rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? -1.0f : rh.ray.tfar;
    }
};
#endif

/// Everything the benchmarks share, made once.
struct BenchData {
    std::string description;
    std::vector<Triangle> triangles = benchTriangles(description);
    std::vector<Bounds3f> bounds = boundsOf(triangles);
    Bvh bvh = buildBvh(bounds);
    std::vector<Triangle> sorted = inLeafOrder(triangles, bvh.primOrder);
    TriangleSceneView view{bvh.nodes.data(), sorted.data(), uint32_t(sorted.size())};
    WideTriangleScene wide = buildWideTriangleScene(triangles);
    WideTriangleSceneView wideView = wide.view();
    WideIsa isa = hostWideIsa();
    std::vector<Ray> primary = primaryRays(frameCity(sceneBounds(triangles), 50.0f, 1024.0f / 768.0f), 1024, 768);
    std::vector<Ray> diffuse = diffuseRays(view, primary);
#if URBIS_HAVE_EMBREE
    EmbreeScene embreeHigh{triangles, RTC_BUILD_QUALITY_HIGH};
    EmbreeScene embreeMedium{triangles, RTC_BUILD_QUALITY_MEDIUM};
#endif
};

const BenchData& data() {
    static const BenchData d;
    return d;
}

enum class RayKind { Primary, Diffuse };
enum class Tracer { Urbis, UrbisWide, EmbreeHigh, EmbreeMedium };

/// Traces rays [b, e) and returns how many hit (also keeps the work from being optimised away).
template <Tracer T>
size_t traceRange(const BenchData& d, const std::vector<Ray>& rays, size_t b, size_t e) {
    size_t hits = 0;
    for (size_t i = b; i < e; ++i) {
        if constexpr (T == Tracer::Urbis) {
            hits += intersectClosest(d.view, rays[i]).valid();
        } else if constexpr (T == Tracer::UrbisWide) {
            hits += traceWideTriangles(d.isa, d.wideView, rays[i], false).valid();
        } else {
#if URBIS_HAVE_EMBREE
            const EmbreeScene& embree = T == Tracer::EmbreeHigh ? d.embreeHigh : d.embreeMedium;
            hits += embree.intersect(rays[i]) >= 0.0f;
#endif
        }
    }
    return hits;
}

template <Tracer T>
void BM_Trace(benchmark::State& state, RayKind kind) {
    const BenchData& d = data();
    const std::vector<Ray>& rays = kind == RayKind::Primary ? d.primary : d.diffuse;
    const bool parallel = state.range(0) > 1;
    size_t hits = 0;
    for (auto _ : state) {
        if (!parallel) {
            hits = traceRange<T>(d, rays, 0, rays.size());
        } else {
            std::atomic<size_t> total{0};
            tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), 1024), [&](const tbb::blocked_range<size_t>& r) {
                total += traceRange<T>(d, rays, r.begin(), r.end());
            });
            hits = total;
        }
        benchmark::DoNotOptimize(hits);
    }
    state.counters["rays_per_second"] =
        benchmark::Counter(double(rays.size()) * double(state.iterations()), benchmark::Counter::kIsRate);
    state.counters["hit_fraction"] = double(hits) / double(rays.size());
    state.counters["rays"] = double(rays.size());
}

/// Builds of urbis's BVH (Wide: the 8-wide compressed one), with its size.
template <bool Wide>
void BM_BuildUrbis(benchmark::State& state) {
    const BenchData& d = data();
    for (auto _ : state) {
        if constexpr (Wide) benchmark::DoNotOptimize(buildWideBvh(d.bounds).nodes.data());
        else benchmark::DoNotOptimize(buildBvh(d.bounds).nodes.data());
    }
    state.counters["triangles_per_second"] =
        benchmark::Counter(double(d.triangles.size()) * double(state.iterations()), benchmark::Counter::kIsRate);
    state.counters["triangles"] = double(d.triangles.size());
    state.counters["nodes"] = double(Wide ? d.wide.bvh.nodes.size() : d.bvh.nodes.size());
    state.counters["node_bytes"] = double(Wide ? d.wide.bvh.nodes.size() * sizeof(WideBvhNode) : d.bvh.nodes.size() * sizeof(BvhNode));
    if (Wide) state.counters["block_bytes"] = double(d.wide.blocks.size() * sizeof(TriangleBlock));
    if (!Wide) state.counters["sah_cost"] = sahCost(d.bvh);
}

#if URBIS_HAVE_EMBREE
void BM_BuildEmbree(benchmark::State& state, RTCBuildQuality quality) {
    const BenchData& d = data();
    for (auto _ : state) {
        EmbreeScene scene(d.triangles, quality);
        benchmark::DoNotOptimize(scene.scene);
    }
    state.counters["triangles_per_second"] =
        benchmark::Counter(double(d.triangles.size()) * double(state.iterations()), benchmark::Counter::kIsRate);
}
#endif

const int kAllCores = int(std::max(1u, std::thread::hardware_concurrency()));

void registerAll() {
    benchmark::RegisterBenchmark("Build/urbis", BM_BuildUrbis<false>)->Unit(benchmark::kMillisecond)->UseRealTime();
    benchmark::RegisterBenchmark("Build/urbis_wide", BM_BuildUrbis<true>)->Unit(benchmark::kMillisecond)->UseRealTime();
#if URBIS_HAVE_EMBREE
    benchmark::RegisterBenchmark("Build/embree_high", BM_BuildEmbree, RTC_BUILD_QUALITY_HIGH)
        ->Unit(benchmark::kMillisecond)->UseRealTime();
    benchmark::RegisterBenchmark("Build/embree_medium", BM_BuildEmbree, RTC_BUILD_QUALITY_MEDIUM)
        ->Unit(benchmark::kMillisecond)->UseRealTime();
#endif
    for (RayKind kind : {RayKind::Primary, RayKind::Diffuse}) {
        const std::string k = kind == RayKind::Primary ? "primary" : "diffuse";
        for (int threads : {1, kAllCores}) {
            const std::string suffix = k + "/threads:" + std::to_string(threads);
            benchmark::RegisterBenchmark(("Trace/urbis/" + suffix).c_str(), BM_Trace<Tracer::Urbis>, kind)
                ->Arg(threads)->Unit(benchmark::kMillisecond)->UseRealTime();
            benchmark::RegisterBenchmark(("Trace/urbis_wide/" + suffix).c_str(), BM_Trace<Tracer::UrbisWide>, kind)
                ->Arg(threads)->Unit(benchmark::kMillisecond)->UseRealTime();
#if URBIS_HAVE_EMBREE
            benchmark::RegisterBenchmark(("Trace/embree_high/" + suffix).c_str(), BM_Trace<Tracer::EmbreeHigh>, kind)
                ->Arg(threads)->Unit(benchmark::kMillisecond)->UseRealTime();
            benchmark::RegisterBenchmark(("Trace/embree_medium/" + suffix).c_str(), BM_Trace<Tracer::EmbreeMedium>,
                                         kind)
                ->Arg(threads)->Unit(benchmark::kMillisecond)->UseRealTime();
#endif
        }
    }
}

/// Console output plus, at the end, urbis / Embree ratios of the same measurement.
class RatioReporter : public benchmark::ConsoleReporter {
public:
    void ReportRuns(const std::vector<Run>& runs) override {
        ConsoleReporter::ReportRuns(runs);
        for (const Run& run : runs) {
            for (const char* counter : {"rays_per_second", "triangles_per_second"}) {
                auto it = run.counters.find(counter);
                if (it != run.counters.end()) rates_[run.benchmark_name()] = it->second.value;
            }
        }
    }
    void Finalize() override {
        ConsoleReporter::Finalize();
        std::printf("\nscene: %s\n", data().description.c_str());
        std::printf("urbis / Embree 3 (build quality HIGH and MEDIUM), same triangles and rays, M/s:\n");
        for (const auto& [name, rate] : rates_) {
            // Names are <what>/<tracer>/<rest>: each urbis tracer against Embree's of the same <what> and <rest>.
            const size_t at = name.find('/'), end = name.find('/', at + 1);
            const bool spread = name.ends_with("_stddev") || name.ends_with("_cv");
            if (at == std::string::npos || spread || name.compare(at + 1, 5, "urbis") != 0) continue;
            std::printf("  %-47s urbis %7.2f", name.c_str(), rate * 1e-6);
            const std::string rest = end == std::string::npos ? "" : name.substr(end);
            for (const char* quality : {"high", "medium"}) {
                auto it = rates_.find(name.substr(0, at) + "/embree_" + quality + rest);
                if (it != rates_.end())
                    std::printf("  %s %7.2f (ratio %.2f)", quality, it->second * 1e-6, rate / it->second);
            }
            std::printf("\n");
        }
    }

private:
    std::map<std::string, double> rates_;
};

} // namespace
} // namespace urbis::bench

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    urbis::bench::registerAll();
    urbis::bench::RatioReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    benchmark::Shutdown();
    return 0;
}
