// The viewer's pictures of a film's AOVs: each layer's values mapped as film/aov_display.h says.
#include "film/aov_display.h"
#include "film/film_output.h"
#include "film/tone_map.h"

#include <gtest/gtest.h>

namespace urbis {
namespace {

/// A 3x1 film with AOVs and two samples a pixel: a surface 1 m away, one 10 km away, and the sky.
Film threePixels() {
    Film film(3, 1, true);
    FilmArrays<HostArray>& a = film.arrays;
    for (size_t i = 0; i < 3; ++i) a.sampleCount[i] = 2;
    a.albedoSum[0] = {1.0f, 0.5f, 0.0f};          // mean (0.5, 0.25, 0)
    a.normalSum[0] = {0.0f, 2.0f, 0.0f};          // mean straight up
    a.depthSum[0] = 2.0f;                         // two hits at 1 m
    a.surfaceCount[0] = 2;
    a.depthSum[1] = 20000.0f;                     // two hits at 10 km
    a.surfaceCount[1] = 2;
    a.objectId[0] = 7;
    a.partId[0] = 1;
    a.radianceSum[0] = {2.0f, 2.0f, 2.0f};        // Y 1 and 1: no error
    a.luminanceSqSum[0] = 2.0f;
    a.radianceSum[1] = {2.0f, 2.0f, 2.0f};        // Y 0 and 2: mean 1, standard error 1, above the 50 % of red
    a.luminanceSqSum[1] = 4.0f;
    return film;
}

TEST(FilmAovDisplay, EachLayerMapsItsValuesAsDocumented) {
    const Film film = threePixels();
    const Rgb8Image albedo = displayImage(film, FilmDisplay::Albedo, 0);
    EXPECT_EQ(albedo.rgb[0], uint8_t(srgbEncode(0.5f) * 255.0f + 0.5f));
    EXPECT_EQ(albedo.rgb[1], uint8_t(srgbEncode(0.25f) * 255.0f + 0.5f));
    EXPECT_EQ(albedo.rgb[2], 0);
    const Rgb8Image normal = displayImage(film, FilmDisplay::Normal, 0);
    EXPECT_EQ(normal.rgb[0], 128);
    EXPECT_EQ(normal.rgb[1], 255);
    const Rgb8Image depth = displayImage(film, FilmDisplay::Depth, 0);
    EXPECT_EQ(depth.rgb[0], 255);   // 1 m: white
    EXPECT_EQ(depth.rgb[3], 0);     // 10 km: black
    EXPECT_EQ(depth.rgb[6], 0);     // the sky: black
    const Rgb8Image ids = displayImage(film, FilmDisplay::Ids, 0);
    EXPECT_GE(ids.rgb[0], 51);      // a surface: at least 0.2 in every channel
    EXPECT_EQ(ids.rgb[6] + ids.rgb[7] + ids.rgb[8], 0);   // the sky
    const Rgb8Image error = displayImage(film, FilmDisplay::Error, 0);
    EXPECT_EQ(error.rgb[0], 0);     // no error: blue
    EXPECT_EQ(error.rgb[2], 255);
    EXPECT_EQ(error.rgb[3], 255);   // 100 % error: red
    EXPECT_EQ(error.rgb[5], 0);
    // The image is the tone-mapped radiance, as a PNG has it.
    EXPECT_EQ(displayImage(film, FilmDisplay::Image, 0).rgb, toneMap(film, 0).rgb);
}

TEST(FilmAovDisplay, LayersNeedAFilmWithAovs) {
    EXPECT_THROW(displayImage(Film(2, 2, false), FilmDisplay::Depth, 0), std::invalid_argument);
    EXPECT_NO_THROW(displayImage(Film(2, 2, false), FilmDisplay::Image, 0));
}

} // namespace
} // namespace urbis
