// The device film: it persists between render calls, accumulates like the CPU's, and its AOVs
// agree with the CPU's AOV pass.
#include "gpu_test_support.h"

#include "cpu/cpu_renderer.h"
#include "film_test_support.h"

#include <cmath>

using namespace urbis;
using namespace urbis::test;

namespace {

constexpr uint32_t kWidth = 48, kHeight = 32;

Film renderOnGpu(GpuScene& gpu, const RenderSettings& settings, std::initializer_list<uint32_t> calls) {
    Film film(settings.width, settings.height, true);
    gpu.setFilm(film);
    RenderCounters counters;
    uint32_t first = 0;
    for (uint32_t count : calls) {
        gpu.render(wallCamera(float(settings.width) / float(settings.height)), settings, {first, count}, counters);
        first += count;
    }
    gpu.readFilm(film);
    return film;
}

} // namespace

TEST(GpuFilm, EightAndEightSamplesAreSixteenBitForBit) {
    URBIS_SKIP_WITHOUT_GPU();
    const Scene scene = wallScene(true);
    std::unique_ptr<GpuScene> gpu = GpuScene::upload(scene);
    const RenderSettings settings = filmSettings(kWidth, kHeight, 16);
    const Film once = renderOnGpu(*gpu, settings, {16});
    const Film twice = renderOnGpu(*gpu, settings, {8, 8});
    EXPECT_EQ(twice.samplesTaken(), 16u);
    expectSameFilmBits(once, twice);
}

TEST(GpuFilm, AovsMatchTheCpu) {
    URBIS_SKIP_WITHOUT_GPU();
    const Scene scene = wallScene(true);
    std::unique_ptr<GpuScene> gpu = GpuScene::upload(scene);
    const RenderSettings settings = filmSettings(kWidth, kHeight, 4);
    const Film onGpu = renderOnGpu(*gpu, settings, {4});
    Film onCpu(kWidth, kHeight, true);
    RenderCounters counters;
    renderCpu(scene.view(), wallCamera(float(kWidth) / float(kHeight)), settings, {0, 4}, onCpu, false, counters);
    const AovImages a = resolveAovs(onCpu), b = resolveAovs(onGpu);
    EXPECT_EQ(a.object, b.object);
    EXPECT_EQ(a.part, b.part);
    EXPECT_EQ(a.samples, b.samples);
    // A camera ray grazing the wall's top edge may hit on one backend only (the GPU's rounding):
    // such pixels, of the horizon's row at most, are left out.
    size_t grazing = 0;
    for (size_t i = 0; i < a.depth.size(); ++i) {
        if (onCpu.arrays.surfaceCount[i] != onGpu.arrays.surfaceCount[i]) {
            ++grazing;
            continue;
        }
        if (std::isinf(a.depth[i])) {
            EXPECT_TRUE(std::isinf(b.depth[i])) << i;
            continue;
        }
        EXPECT_NEAR(a.depth[i], b.depth[i], 1e-3f * a.depth[i]) << i;
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(a.albedo[i][c], b.albedo[i][c], 1e-5f) << i;
            EXPECT_NEAR(a.normal[i][c], b.normal[i][c], 1e-5f) << i;
        }
    }
    EXPECT_LE(grazing, size_t(kWidth));
}
