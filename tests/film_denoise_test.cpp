// The denoiser on synthetic films and on a small render: textures under constant light stay as
// they are, pixels of one object never see another's, and the result is the same for any thread
// count. The MSE goal against converged renders is film_denoise_city_test.cpp.
#include "cpu/cpu_denoiser.h"
#include "cpu/cpu_renderer.h"
#include "film_test_support.h"

#include <tbb/global_control.h>

#include <cmath>
#include <cstring>
#include <stdexcept>

using namespace urbis;
using namespace urbis::test;

namespace {

constexpr uint32_t kWidth = 40, kHeight = 24, kSamples = 4;

/// A deterministic number in [0, 1) for pixel `p` and sample `s`.
float hashUnit(uint32_t p, uint32_t s) {
    uint32_t h = p * 0x9e3779b1u ^ (s + 1) * 0x85ebca77u;
    h ^= h >> 15;
    h *= 0x2c1b3c6du;
    h ^= h >> 13;
    return float(h >> 8) / float(1u << 24);
}

/// A film of kSamples samples per pixel of one plane facing the camera (normal +z, depth rising
/// along x), with `id(x, y)`, `albedo(x, y)` and radiance `sample(x, y, s)` for sample s.
template <class Id, class Albedo, class Sample>
Film syntheticFilm(Id id, Albedo albedo, Sample sample) {
    Film film(kWidth, kHeight, true);
    FilmArrays<HostArray>& a = film.arrays;
    for (uint32_t y = 0; y < kHeight; ++y)
        for (uint32_t x = 0; x < kWidth; ++x) {
            const size_t p = size_t(y) * kWidth + x;
            for (uint32_t s = 0; s < kSamples; ++s) {
                const Vec3f radiance = sample(x, y, s);
                a.radianceSum[p] += radiance;
                a.luminanceSqSum[p] += luminance(radiance) * luminance(radiance);
                a.albedoSum[p] += albedo(x, y);
                a.normalSum[p] += Vec3f{0, 0, 1};
                a.positionSum[p] += Vec3f{float(x), float(y), 0};
                a.depthSum[p] += 20.0f + 0.1f * float(x);
            }
            a.sampleCount[p] = a.surfaceCount[p] = kSamples;
            a.objectId[p] = id(x, y);
            a.partId[p] = uint32_t(SurfacePart::Facade);
        }
    return film;
}

Vec3f checkerAlbedo(uint32_t x, uint32_t y) {
    return ((x / 2 + y / 2) % 2) ? Vec3f{0.8f, 0.7f, 0.5f} : Vec3f{0.1f, 0.2f, 0.05f};
}

} // namespace

// A checkerboard texture (2-pixel squares) under constant light: demodulated, the light is one
// constant that no weight can change, so every pixel keeps its radiance (within float rounding).
TEST(FilmDenoise, TextureUnderConstantLightStaysAsItIs) {
    const Vec3f light{2.0f, 1.8f, 1.5f};
    const auto radiance = [&](uint32_t x, uint32_t y) {
        const Vec3f a = checkerAlbedo(x, y);
        return Vec3f{a.x * light.x, a.y * light.y, a.z * light.z};
    };
    Film film = syntheticFilm([](uint32_t, uint32_t) { return 3u; }, checkerAlbedo,
                              [&](uint32_t x, uint32_t y, uint32_t) { return radiance(x, y); });
    denoiseCpu(film);
    float worst = 0;
    for (uint32_t y = 0; y < kHeight; ++y)
        for (uint32_t x = 0; x < kWidth; ++x) {
            const Vec3f got = meanRadiance(film, size_t(y) * kWidth + x), want = radiance(x, y);
            for (int c = 0; c < 3; ++c) worst = std::max(worst, std::fabs(got[c] / want[c] - 1.0f));
        }
    EXPECT_LT(worst, 1e-5f) << "largest relative change of a pixel";
}

// Two objects side by side in one plane (same depth and normal: only the id tells them apart),
// noisy, one five times as bright: the left one's pixels come out bit for bit the same whatever the
// right one holds, and closer to its own mean than before (RMS distance at most half the noisy one's).
TEST(FilmDenoise, NeverMixesTwoObjects) {
    const auto id = [](uint32_t x, uint32_t) { return x < kWidth / 2 ? 1u : 2u; };
    const auto white = [](uint32_t, uint32_t) { return Vec3f{0.5f, 0.5f, 0.5f}; };
    const auto noisy = [&](float rightScale) {
        return [=](uint32_t x, uint32_t y, uint32_t s) {
            const float mean = x < kWidth / 2 ? 1.0f : 5.0f * rightScale;
            return Vec3f{1, 1, 1} * (mean * 2.0f * hashUnit(y * kWidth + x, s));
        };
    };
    const Film before = syntheticFilm(id, white, noisy(1.0f));
    Film once = before;
    Film other = syntheticFilm(id, white, noisy(10.0f));
    denoiseCpu(once);
    denoiseCpu(other);
    double squaresBefore = 0, squaresAfter = 0;
    for (uint32_t y = 0; y < kHeight; ++y)
        for (uint32_t x = 0; x < kWidth / 2; ++x) {
            const size_t p = size_t(y) * kWidth + x;
            EXPECT_EQ(std::memcmp(&once.arrays.radianceSum[p], &other.arrays.radianceSum[p], sizeof(Vec3f)), 0)
                << "pixel " << x << "," << y;
            squaresBefore += std::pow(meanRadiance(before, p).x - 1.0, 2);
            squaresAfter += std::pow(meanRadiance(once, p).x - 1.0, 2);
        }
    EXPECT_LT(std::sqrt(squaresAfter), 0.5 * std::sqrt(squaresBefore)) << "RMS distance from the left object's mean";
}

TEST(FilmDenoise, SameBitsForAnyThreadCount) {
    const Scene scene = wallScene(true);
    const RenderSettings settings = filmSettings(64, 48, 4);
    Film film(settings.width, settings.height, true);
    RenderCounters counters;
    renderCpu(scene.view(), wallCamera(64.0f / 48.0f), settings, {0, 4}, film, false, counters);
    Film one = film, three = film;
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
        denoiseCpu(one);
    }
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 3);
        denoiseCpu(three);
    }
    expectSameFilmBits(one, three);
    // And it did something: the wall's pixels changed.
    EXPECT_NE(std::memcmp(one.arrays.radianceSum.data(), film.arrays.radianceSum.data(), film.pixels() * sizeof(Vec3f)), 0);
}

TEST(FilmDenoise, NeedsAovs) {
    Film film(8, 8, false);
    EXPECT_THROW(denoiseCpu(film), std::invalid_argument);
}
