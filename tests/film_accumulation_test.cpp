// The film accumulates: samples added in any split of calls give the same bits, on any thread count.
#include "cpu/cpu_renderer.h"
#include "film_test_scene.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cstring>

using namespace urbis;
using namespace urbis::test;

namespace {

/// Whether two films hold the same bits in every array.
void expectSameBits(const Film& a, const Film& b) {
    ASSERT_EQ(a.width, b.width);
    ASSERT_EQ(a.height, b.height);
    int arrays = 0;
    forEachFilmArray(
        [&](auto, bool, const auto& x, const auto& y) {
            ++arrays;
            ASSERT_EQ(x.size(), y.size());
            EXPECT_EQ(std::memcmp(x.data(), y.data(), x.size() * sizeof(x[0])), 0) << "array " << arrays;
        },
        a.arrays, b.arrays);
    EXPECT_EQ(arrays, 9);
}

Film renderFilm(const Scene& scene, const RenderSettings& settings, std::initializer_list<uint32_t> calls) {
    Film film(settings.width, settings.height, true);
    RenderCounters counters;
    for (uint32_t count : calls)
        renderCpu(scene.view(), wallCamera(float(settings.width) / float(settings.height)), settings,
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
    expectSameBits(once, twice);
    expectSameBits(once, renderFilm(scene, settings, {1, 5, 10}));
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
    for (int threads : {2, 5}) expectSameBits(one, renderWith(threads));
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
