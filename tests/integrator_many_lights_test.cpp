// Many lights (docs/lights.md § The light BVH): 1,000 small emitters (2,000 triangle lights) over a
// plane converge to the same image under the uniform, power, light-BVH and colliders samplers (MIS
// keeps each unbiased), and at equal samples the light BVH's error is well below the power
// sampler's.
#include "cpu/cpu_renderer.h"
#include "lights_test_scenes.h"
#include "scene/camera.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace urbis;

namespace {

constexpr uint32_t kSide = 32;  // pixels
constexpr uint32_t kBlocks = 4; // per side: block means compared

LinearImage render(const Scene& scene, LightSamplerKind sampler, uint32_t spp, uint32_t seed) {
    RenderSettings settings;
    settings.width = settings.height = kSide;
    settings.spp = spp;
    settings.seed = seed;
    settings.lightSampler = sampler;
    // 2.5 m up, looking 32 degrees down with a 40 degree field: the view's top edge points 12 degrees
    // down, so no emitter (all 3 m up or higher) is seen directly and the image is the light they
    // throw on the ground, which is what the samplers estimate (a visible emitter's edges would add
    // the same aliasing noise to every sampler).
    const Camera camera = makeLookAtCamera(Vec3f{0, 2.5f, 0}, Vec3f{0, 0, -4}, 40.0f, 1.0f);
    RenderCounters counters;
    return renderCpu(scene.view(), camera, settings, false, counters);
}

/// Mean luminance of each of kBlocks x kBlocks blocks, and its standard error from the spread of the
/// block's pixels (which also holds the image's own variation over the block: an upper bound).
struct Blocks {
    std::vector<double> mean, error;
};

Blocks blockMeans(const LinearImage& image) {
    const uint32_t b = kSide / kBlocks, n = b * b;
    Blocks out{std::vector<double>(kBlocks * kBlocks, 0.0), std::vector<double>(kBlocks * kBlocks, 0.0)};
    std::vector<double> squares(kBlocks * kBlocks, 0.0);
    for (uint32_t y = 0; y < kSide; ++y)
        for (uint32_t x = 0; x < kSide; ++x) {
            const double l = luminance(image.pixels[y * kSide + x]);
            out.mean[(y / b) * kBlocks + x / b] += l / n;
            squares[(y / b) * kBlocks + x / b] += l * l / n;
        }
    for (size_t i = 0; i < out.mean.size(); ++i)
        out.error[i] = std::sqrt(std::max(0.0, squares[i] - out.mean[i] * out.mean[i]) / (n - 1));
    return out;
}

/// Relative RMSE of luminance against `reference` (pixels of reference luminance below 1e-3 left out).
double relativeRmse(const LinearImage& image, const LinearImage& reference) {
    double sum = 0;
    size_t n = 0;
    for (size_t i = 0; i < image.pixels.size(); ++i) {
        const double r = luminance(reference.pixels[i]);
        if (r < 1e-3) continue;
        const double d = (luminance(image.pixels[i]) - r) / r;
        sum += d * d;
        ++n;
    }
    return std::sqrt(sum / double(n));
}

Scene nightPlane() {
    Scene scene = test::manyEmitterScene(1000, 200.0f);
    buildLights(scene);
    return scene;
}

} // namespace

// Each block's mean within 4 standard errors (of both images) of the reference's; the light BVH's
// also within 5 %.
TEST(IntegratorManyLights, SamplersConvergeToOneImage) {
    const Scene scene = nightPlane();
    const Blocks expected = blockMeans(render(scene, LightSamplerKind::Bvh, 1024, 99));
    for (LightSamplerKind sampler : {LightSamplerKind::Uniform, LightSamplerKind::Power, LightSamplerKind::Bvh,
                                     LightSamplerKind::Colliders}) {
        const Blocks got = blockMeans(render(scene, sampler, 256, 1));
        double worst = 0;
        for (size_t b = 0; b < got.mean.size(); ++b) {
            const double error = std::hypot(got.error[b], expected.error[b]);
            EXPECT_NEAR(got.mean[b], expected.mean[b], 4.0 * error) << "sampler " << int(sampler) << ", block " << b;
            if (sampler == LightSamplerKind::Bvh) {
                EXPECT_NEAR(got.mean[b] / expected.mean[b], 1.0, 0.05) << "block " << b;
            }
            worst = std::max(worst, std::fabs(got.mean[b] - expected.mean[b]) / error);
        }
        std::printf("sampler %d: largest block difference %.2f standard errors\n", int(sampler), worst);
    }
}

TEST(IntegratorManyLights, BvhBeatsPowerAtEqualSamples) {
    const Scene scene = nightPlane();
    const LinearImage reference = render(scene, LightSamplerKind::Bvh, 1024, 99);
    const double bvh = relativeRmse(render(scene, LightSamplerKind::Bvh, 16, 1), reference);
    const double power = relativeRmse(render(scene, LightSamplerKind::Power, 16, 1), reference);
    RecordProperty("bvh", std::to_string(bvh));
    RecordProperty("power", std::to_string(power));
    std::printf("relative RMSE at 16 spp: bvh %.4f, power %.4f\n", bvh, power);
    EXPECT_LT(bvh, 0.5 * power);
}
