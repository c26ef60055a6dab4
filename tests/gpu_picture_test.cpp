// The viewer's picture made on the GPU (GpuScene::drawPicture, the same displayPixel of
// film/display_pixel.h as the CPU's displayImage) against the CPU's, of one film with AOVs, every
// layer. The GPU's fast math (powf, log10f, division) may move a value across a rounding boundary:
// at most 1 level of 255 apart in any channel, and at most 1 % of the channels apart at all. A
// denoised picture leaves the device film's sums as they were.
#include "gpu_test_support.h"

#include "cpu/cpu_renderer.h"
#include "film/aov_display.h"
#include "film_test_support.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <iterator>

using namespace urbis;
using namespace urbis::test;

namespace {

/// The wall scene's film of `spp` samples with AOVs, rendered on the CPU, and the scene on the GPU holding it.
struct FilmOnBoth {
    Scene scene = wallScene(true);
    Film film;
    std::unique_ptr<GpuScene> gpu;
    FilmOnBoth(uint32_t width, uint32_t height, uint32_t spp) : film(width, height, true) {
        RenderCounters counters;
        renderCpu(scene.view(), wallCamera(float(width) / float(height)), filmSettings(width, height, spp), {0, spp}, film,
                  false, counters);
        gpu = GpuScene::upload(scene);
        gpu->setFilm(film);
    }
};

} // namespace

TEST(GpuPicture, EveryLayerAgreesWithTheCpuWithinALevel) {
    URBIS_SKIP_WITHOUT_GPU();
    FilmOnBoth both(96, 64, 4);
    const Film& film = both.film;
    GpuScene* gpu = both.gpu.get();
    for (size_t d = 0; d < std::size(kFilmDisplayNames); ++d) {
        const FilmDisplay display = FilmDisplay(d);
        const Rgb8Image cpu = displayImage(film, display, 0.5f);
        gpu->drawPicture(display, 0.5f, false);
        const Rgb8Image device = gpu->readPicture();
        ASSERT_EQ(device.rgb.size(), cpu.rgb.size()) << kFilmDisplayNames[d];
        size_t apart = 0;
        int worst = 0;
        for (size_t i = 0; i < cpu.rgb.size(); ++i) {
            const int difference = std::abs(int(cpu.rgb[i]) - int(device.rgb[i]));
            apart += difference != 0;
            worst = std::max(worst, difference);
        }
        EXPECT_LE(worst, 1) << kFilmDisplayNames[d];
        EXPECT_LE(apart, cpu.rgb.size() / 100) << kFilmDisplayNames[d];
    }
}

TEST(GpuPicture, ADenoisedPictureKeepsTheFilmsSums) {
    URBIS_SKIP_WITHOUT_GPU();
    FilmOnBoth both(64, 48, 2);
    const Film& film = both.film;
    GpuScene* gpu = both.gpu.get();
    gpu->drawPicture(FilmDisplay::Image, 0.0f, false);
    const Rgb8Image noisy = gpu->readPicture();
    gpu->drawPicture(FilmDisplay::Image, 0.0f, true);
    EXPECT_NE(gpu->readPicture().rgb, noisy.rgb) << "the filter changed the picture";
    Film after;
    gpu->readFilm(after);
    EXPECT_EQ(after.arrays.radianceSum.size(), film.arrays.radianceSum.size());
    EXPECT_EQ(std::memcmp(after.arrays.radianceSum.data(), film.arrays.radianceSum.data(),
                          film.arrays.radianceSum.size() * sizeof(Vec3f)), 0);
}
