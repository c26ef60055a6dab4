// The photon integrators on the GPU against the CPU (docs/photons.md): on the street canyon the
// photon map's and the photon buffers' images agree within noise (GPU photons scatter with fast-math
// shading, so the photons differ from the CPU's after their first bounces), the buffers flag the same
// blocks, and the photon map stores about as many photons.
#include "render/renderer.h"
#include "gpu_test_support.h"
#include "photon_test_scenes.h"

#include <cmath>

using namespace urbis;

namespace {

double meanLuminance(const LinearImage& image) {
    double sum = 0;
    for (const Vec3f& p : image.pixels) sum += luminance(p);
    return sum / double(image.pixels.size());
}

/// Mean relative difference of luminance over blocks of 4 x 4 pixels.
double blockDifference(const LinearImage& a, const LinearImage& b) {
    double sum = 0;
    uint32_t count = 0;
    for (uint32_t by = 0; by + 4 <= a.height; by += 4)
        for (uint32_t bx = 0; bx + 4 <= a.width; bx += 4) {
            double la = 0, lb = 0;
            for (uint32_t y = by; y < by + 4; ++y)
                for (uint32_t x = bx; x < bx + 4; ++x) {
                    la += luminance(a.pixels[size_t(y) * a.width + x]);
                    lb += luminance(b.pixels[size_t(y) * b.width + x]);
                }
            sum += std::fabs(la - lb) / std::max(lb, 1e-9);
            ++count;
        }
    return sum / count;
}

} // namespace

TEST(GpuPhotons, CpuAndGpuAgreeOnTheStreetCanyon) {
    URBIS_SKIP_WITHOUT_GPU();
    const Scene scene = test::streetCanyonScene();
    const Camera camera = test::streetCanyonCamera(1.5f);
    RenderSettings settings;
    settings.width = 96;
    settings.height = 64;
    settings.spp = 64;
    settings.photonsPerPass = 20000;
    settings.photonRadius = 1.5f;
    for (IntegratorKind kind : {IntegratorKind::PhotonMap, IntegratorKind::PhotonBuffers}) {
        settings.integrator = kind;
        const char* name = kind == IntegratorKind::PhotonMap ? "photon map" : "photon buffers";
        Film cpuFilm(settings.width, settings.height, false), gpuFilm(settings.width, settings.height, false);
        RenderCounters counters;
        DeviceReport cpuReport, gpuReport;
        Renderer::make(scene, kind, {"cpu", {}, 0, false, nullptr})
            ->render(camera, settings, SampleRange{0, settings.spp}, cpuFilm, false, false, counters, cpuReport);
        Renderer::make(scene, kind, {"cuda", {}, 0, false, nullptr})
            ->render(camera, settings, SampleRange{0, settings.spp}, gpuFilm, false, false, counters, gpuReport);
        ASSERT_TRUE(cpuReport.photons && gpuReport.photons) << name;
        const PhotonTimings& cpuTimings = *cpuReport.photons;
        const PhotonTimings& gpuTimings = *gpuReport.photons;
        const LinearImage cpuImage = meanRadiance(cpuFilm), gpuImage = meanRadiance(gpuFilm);
        EXPECT_NEAR(meanLuminance(gpuImage) / meanLuminance(cpuImage), 1.0, 0.02) << name;
        EXPECT_LT(blockDifference(gpuImage, cpuImage), 0.06) << name;
        EXPECT_EQ(gpuTimings.blocksWithMemory, cpuTimings.blocksWithMemory) << name;
        EXPECT_EQ(gpuTimings.texels, cpuTimings.texels) << name;
        if (kind == IntegratorKind::PhotonMap) {
            EXPECT_NEAR(double(gpuTimings.stored) / double(cpuTimings.stored), 1.0, 0.02) << name;
        }
        std::printf("%s: mean luminance cpu %.5f gpu %.5f, block difference %.4f; camera pass cpu %.3f s gpu %.4f s\n", name,
                    meanLuminance(cpuImage), meanLuminance(gpuImage), blockDifference(gpuImage, cpuImage), cpuTimings.camera,
                    gpuTimings.camera);
    }
}
