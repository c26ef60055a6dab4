// The film accumulates: samples added in any split of calls give the same bits, on any thread count.
#include "cpu/cpu_renderer.h"
#include "film_test_support.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cstring>
#include <optional>

using namespace urbis;
using namespace urbis::test;

namespace {

Film renderFilm(const Scene& scene, const RenderSettings& settings, std::initializer_list<uint32_t> calls,
                std::optional<Camera> camera = {}) {
    Film film(settings.width, settings.height, true);
    RenderCounters counters;
    for (uint32_t count : calls)
        renderCpu(scene.view(), camera.value_or(wallCamera(float(settings.width) / float(settings.height))), settings,
                  film.nextSamples(count), film, false, counters);
    return film;
}

} // namespace

TEST(FilmAccumulation, EightAndEightSamplesAreSixteenBitForBit) {
    const Scene scene = wallScene(true);
    const RenderSettings settings = filmSettings(40, 30, 16);
    const Film once = renderFilm(scene, settings, {16});
    const Film twice = renderFilm(scene, settings, {8, 8});
    EXPECT_EQ(once.samplesTaken(), 16u);
    expectSameFilmBits(once, twice);
    expectSameFilmBits(once, renderFilm(scene, settings, {1, 5, 10}));
    // The scene is not trivial: the sun lights the wall unevenly and its mean differs from 8 spp's.
    const LinearImage eight = meanRadiance(renderFilm(scene, settings, {8}));
    const LinearImage sixteen = meanRadiance(once);
    EXPECT_NE(std::memcmp(eight.pixels.data(), sixteen.pixels.data(), eight.pixels.size() * sizeof(Vec3f)), 0);
}

TEST(FilmAccumulation, SameFilmForAnyThreadCount) {
    const Scene scene = wallScene(true);
    const RenderSettings settings = filmSettings(48, 40, 4);
    auto renderWith = [&](int threads) {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
        return renderFilm(scene, settings, {2, 2});
    };
    const Film one = renderWith(1);
    for (int threads : {2, 5}) expectSameFilmBits(one, renderWith(threads));
}

TEST(FilmAccumulation, MeanIsTheSumOverTheSamples) {
    const Scene scene = wallScene(true);
    const RenderSettings settings = filmSettings(16, 12, 6);
    RenderCounters counters;
    const LinearImage direct = renderCpu(scene.view(), wallCamera(16.0f / 12.0f), settings, false, counters);
    EXPECT_GT(counters.rays, 16u * 12u * 6u);
    const Film film = renderFilm(scene, settings, {6});
    const LinearImage mean = meanRadiance(film);
    ASSERT_EQ(mean.pixels.size(), direct.pixels.size());
    for (size_t i = 0; i < mean.pixels.size(); ++i) {
        const Vec3f expected = film.arrays.radianceSum[i] / 6.0f;
        for (int c = 0; c < 3; ++c) {
            EXPECT_EQ(mean.pixels[i][c], expected[c]);
            EXPECT_EQ(direct.pixels[i][c], expected[c]);
        }
    }
}

TEST(FilmAccumulation, AnEmptyFilmIsBlackWithSkyIds) {
    const Film film(4, 3, true);
    EXPECT_EQ(film.samplesTaken(), 0u);
    EXPECT_EQ(film.nextSamples(5).first, 0u);
    for (const Vec3f& p : meanRadiance(film).pixels) EXPECT_EQ(maxComponent(p), 0.0f);
    const AovImages aovs = resolveAovs(film);
    for (size_t i = 0; i < film.pixels(); ++i) {
        EXPECT_EQ(aovs.object[i], kSkyId);
        EXPECT_EQ(aovs.part[i], kSkyId);
        EXPECT_TRUE(std::isinf(aovs.depth[i]));
    }
    EXPECT_FALSE(Film(4, 3, false).hasAovs());
    EXPECT_EQ(Film::bytesFor(4, 3, false), 12 * (sizeof(Vec3f) + sizeof(uint32_t)));
}

TEST(FilmAccumulation, RefusesAFilmOfAnotherSize) {
    const Scene scene = wallScene();
    Film film(8, 8, false);
    RenderCounters counters;
    EXPECT_THROW(renderCpu(scene.view(), wallCamera(1.0f), filmSettings(8, 9, 1), {0, 1}, film, false, counters),
                 std::invalid_argument);
}

// A black emitting wall under a black sky: a path sample's radiance is 1 exactly when its camera ray
// hits the wall, so in the horizon's row, where the jitter decides, the AOV pass must count the
// same hits as the path tracer: it traces the same camera rays.
TEST(FilmAccumulation, AovPassTracesThePathTracersCameraRays) {
    Scene scene = wallScene();
    Material glowing{Vec3f{0, 0, 0}};
    glowing.emission = Vec3f{1, 1, 1};
    scene.materials[0] = glowing;
    scene.sky = Sky::uniform(Vec3f{0, 0, 0});
    const RenderSettings settings = filmSettings(32, 24, 16);
    // Half a pixel below the wall's top, so that its edge crosses the middle of a row.
    const Camera camera = makeLookAtCamera(Vec3f{0, kWallTop - 0.6f, kWallDistance}, Vec3f{0, kWallTop - 0.6f, 0},
                                           40.0f, 32.0f / 24.0f);
    const Film film = renderFilm(scene, settings, {16}, camera);
    size_t mixed = 0;
    for (size_t i = 0; i < film.pixels(); ++i) {
        EXPECT_EQ(film.arrays.radianceSum[i].x, float(film.arrays.surfaceCount[i])) << "pixel " << i;
        mixed += film.arrays.surfaceCount[i] > 0 && film.arrays.surfaceCount[i] < 16;
    }
    EXPECT_GE(mixed, 30u) << "the horizon's row should mix wall and sky";
}
