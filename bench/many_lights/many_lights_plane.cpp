// Equal-time error of the light samplers on the many-lights test bed (tests/lights_test_scenes.h:
// small emitting squares over a plane at night): each sampler renders progressively, one sample per
// pixel at a time, until its time is spent, and its relative MSE against a converged reference of
// the light BVH (another seed) is printed as a Markdown table (BENCHMARKS.md § Many lights).
// bench/many_lights.sh does the same through `urbis render` for any scene, on either backend.
//
// usage: urbis_many_lights [EMITTERS=5000] [SIDE_M=1000] [SECONDS=20] [REFERENCE_SPP=2048] [WIDTH=192] [HEIGHT=108]
#include "cpu/cpu_renderer.h"
#include "description/scene_description.h"
#include "film/film.h"
#include "lights_test_scenes.h"
#include "scene/camera.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>

using namespace urbis;

namespace {

using Clock = std::chrono::steady_clock;

/// Relative MSE of luminance, (x - r)^2 / (r^2 + 1e-2 m^2) averaged over pixels, m the reference's
/// mean (bench/exr_error.py's).
double relativeMse(const LinearImage& image, const LinearImage& reference) {
    double mean = 0;
    for (const Vec3f& p : reference.pixels) mean += luminance(p) / double(reference.pixels.size());
    double sum = 0;
    for (size_t i = 0; i < image.pixels.size(); ++i) {
        const double r = luminance(reference.pixels[i]), d = luminance(image.pixels[i]) - r;
        sum += d * d / (r * r + 1e-2 * mean * mean);
    }
    return sum / double(image.pixels.size());
}

struct Run {
    LinearImage image;
    uint32_t spp = 0;
    double seconds = 0;
};

/// Renders one sample per pixel at a time until `seconds` have passed or `maxSpp` are taken.
Run renderFor(const SceneView& scene, const Camera& camera, RenderSettings settings, double seconds, uint32_t maxSpp) {
    Film film(settings.width, settings.height, false);
    RenderCounters counters;
    const auto start = Clock::now();
    Run run;
    while (film.samplesTaken() < maxSpp &&
           (run.seconds = std::chrono::duration<double>(Clock::now() - start).count()) < seconds)
        renderCpu(scene, camera, settings, film.nextSamples(1), film, false, counters);
    run.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    run.spp = film.samplesTaken();
    run.image = meanRadiance(film);
    return run;
}

uint32_t argument(int argc, char** argv, int i, uint32_t fallback) {
    return argc > i ? uint32_t(std::strtoul(argv[i], nullptr, 10)) : fallback;
}

} // namespace

int main(int argc, char** argv) {
    const uint32_t emitters = argument(argc, argv, 1, 5000), side = argument(argc, argv, 2, 1000);
    const double seconds = argument(argc, argv, 3, 20);
    const uint32_t referenceSpp = argument(argc, argv, 4, 2048);
    RenderSettings settings;
    settings.width = argument(argc, argv, 5, 192);
    settings.height = argument(argc, argv, 6, 108);
    auto t0 = Clock::now();
    Scene scene = test::manyEmitterScene(emitters, float(side));
    buildLights(scene);
    std::printf("%u emitters (%zu lights) over %u m: scene and lights built in %.2f s\n", emitters,
                scene.lightRecords.size(), side, std::chrono::duration<double>(Clock::now() - t0).count());
    const SceneView view = scene.view();
    // At eye level, looking down at the street (the top of the view points 12 degrees down): no
    // emitter is in view, whose edges' aliasing would add the same error to every sampler.
    const Camera camera = makeLookAtCamera(Vec3f{0, 2.5f, 0}, Vec3f{0, 0, -4}, 40.0f, float(settings.width) / float(settings.height));
    settings.lightSampler = LightSamplerKind::Bvh;
    settings.seed = 9001;
    const Run reference = renderFor(view, camera, settings, 1e9, referenceSpp);
    std::printf("reference: light BVH, %u spp, %.1f s\n\n", reference.spp, reference.seconds);
    std::printf("| sampler | spp in %.0f s | rel. MSE | / bvh's |\n|---|---|---|---|\n", seconds);
    settings.seed = 1;
    double bvh = 0;
    for (LightSamplerKind kind : {LightSamplerKind::Bvh, LightSamplerKind::Colliders, LightSamplerKind::Uniform, LightSamplerKind::Power}) {
        settings.lightSampler = kind;
        const Run run = renderFor(view, camera, settings, seconds, UINT32_MAX);
        const double error = relativeMse(run.image, reference.image);
        if (kind == LightSamplerKind::Bvh) bvh = error;
        std::printf("| %s | %u | %.4g | %.2f |\n", nameOfChoice(kLightSamplers, kind), run.spp, error, error / bvh);
        std::fflush(stdout);
    }
    return 0;
}
