// The denoiser's CUDA kernels against the CPU's passes (the same URBIS_HD functions of
// film/denoise_filter.h): one noisy film with AOVs, denoised on both. The GPU's fast math (expf,
// powf, contracted multiply-adds, approximate division) moves the weights by a few ulps, and near a
// tie it may pick the other one-sided depth slope, so pixels agree within a tolerance, not bit for
// bit: at most 1 % of the channels differ by over 1 % of their value (or 1e-4 where darker), none
// by over 10 %, and the image's mean within 0.1 %.
#include "gpu_test_support.h"

#include "cpu/cpu_denoiser.h"
#include "cpu/cpu_renderer.h"
#include "film_test_support.h"

#include <algorithm>
#include <cmath>

using namespace urbis;
using namespace urbis::test;

TEST(GpuDenoise, AgreesWithTheCpu) {
    URBIS_SKIP_WITHOUT_GPU();
    constexpr uint32_t kWidth = 96, kHeight = 64;
    const Scene scene = wallScene(true);
    const RenderSettings settings = filmSettings(kWidth, kHeight, 4);
    Film noisy(kWidth, kHeight, true);
    RenderCounters counters;
    renderCpu(scene.view(), wallCamera(float(kWidth) / float(kHeight)), settings, {0, 4}, noisy, false, counters);

    Film onCpu = noisy;
    denoiseCpu(onCpu);
    std::unique_ptr<GpuScene> gpu = GpuScene::upload(scene);
    gpu->setFilm(noisy);
    gpu->denoise();
    Film onGpu;
    gpu->readFilm(onGpu);

    double worst = 0, meanCpu = 0, meanGpu = 0;
    size_t changed = 0, far = 0;
    for (size_t i = 0; i < noisy.pixels(); ++i) {
        const Vec3f a = meanRadiance(onCpu, i), b = meanRadiance(onGpu, i), n = meanRadiance(noisy, i);
        for (int c = 0; c < 3; ++c) {
            const double difference = std::fabs(double(a[c]) - b[c]) / std::max(std::fabs(double(a[c])), 1e-2);
            worst = std::max(worst, difference);
            far += difference > 0.01;
            meanCpu += a[c];
            meanGpu += b[c];
        }
        changed += a.x != n.x;
    }
    EXPECT_LE(far, 3 * noisy.pixels() / 100) << "channels over 1 % apart";
    EXPECT_LT(worst, 0.1) << "largest relative difference of a channel";
    EXPECT_NEAR(meanGpu / meanCpu, 1.0, 1e-3) << "image mean";
    EXPECT_GT(changed, noisy.pixels() / 4) << "the filter changed the wall's pixels";
    // The sky is left as it was on both.
    EXPECT_EQ(std::memcmp(&onGpu.arrays.radianceSum[0], &noisy.arrays.radianceSum[0], sizeof(Vec3f)), 0);
}
