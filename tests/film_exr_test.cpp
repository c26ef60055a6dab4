// EXR output read back with OpenEXR's own reader: every layer there, with the analytic values of a
// wall seen head-on under the sky.
#include "cpu/cpu_renderer.h"
#include "film/film_output.h"
#include "film_test_support.h"
#include "process_scratch_dir.h"

#include "film_exr_read.h"

#include <Imath/half.h>
#include <gtest/gtest.h>

#include <cmath>

using namespace urbis;
using namespace urbis::test;

namespace {

constexpr uint32_t kWidth = 32, kHeight = 24, kSpp = 8;

std::string renderWallExr(const char* name, bool exrFloat, float exposureEv, Film* keep = nullptr) {
    const Scene scene = wallScene();
    const RenderSettings settings = filmSettings(kWidth, kHeight, kSpp);
    Film film(kWidth, kHeight, true);
    RenderCounters counters;
    renderCpu(scene.view(), wallCamera(float(kWidth) / float(kHeight)), settings, film.nextSamples(kSpp), film, false,
              counters);
    const std::string path = (processScratchDir() / name).string();
    writeFilm(film, path, FilmOutputOptions{exposureEv, exrFloat});
    if (keep) *keep = film;
    return path;
}

// The upper half of the image sees the sky, the lower half the wall; the rows at the horizon mix.
bool skyRow(uint32_t y) { return y < kHeight / 2 - 1; }
bool wallRow(uint32_t y) { return y > kHeight / 2; }

} // namespace

TEST(FilmExr, EveryLayerWithItsType) {
    const ExrRead exr = readExr(renderWallExr("layers.exr", false, 0.0f));
    EXPECT_EQ(exr.width, int(kWidth));
    EXPECT_EQ(exr.height, int(kHeight));
    const std::map<std::string, Imf::PixelType> expected = {
        {"R", Imf::HALF},          {"G", Imf::HALF},          {"B", Imf::HALF},          {"A", Imf::HALF},
        {"albedo.R", Imf::HALF},   {"albedo.G", Imf::HALF},   {"albedo.B", Imf::HALF},   {"normal.X", Imf::HALF},
        {"normal.Y", Imf::HALF},   {"normal.Z", Imf::HALF},   {"depth.Z", Imf::FLOAT},   {"position.X", Imf::FLOAT},
        {"position.Y", Imf::FLOAT}, {"position.Z", Imf::FLOAT}, {"id.object", Imf::UINT}, {"id.part", Imf::UINT},
        {"samples", Imf::UINT}};
    EXPECT_EQ(exr.types, expected);
}

TEST(FilmExr, FloatColourOnRequest) {
    const ExrRead exr = readExr(renderWallExr("float.exr", true, 0.0f));
    for (const char* name : {"R", "G", "B", "A", "albedo.R", "normal.Z", "depth.Z"})
        EXPECT_EQ(exr.types.at(name), Imf::FLOAT) << name;
    EXPECT_EQ(exr.types.at("id.object"), Imf::UINT);
}

TEST(FilmExr, WallSeenHeadOn) {
    const ExrRead exr = readExr(renderWallExr("wall.exr", false, 0.0f));
    const Camera camera = wallCamera(float(kWidth) / float(kHeight));
    int wallPixels = 0;
    for (uint32_t y = 0; y < kHeight; ++y) {
        if (!wallRow(y)) continue;
        for (uint32_t x = 0; x < kWidth; ++x) {
            const size_t i = size_t(y) * kWidth + x;
            ++wallPixels;
            // Z depth of a plane seen head-on: its distance, in every pixel (not the ray's length).
            EXPECT_NEAR(exr.floats.at("depth.Z")[i], kWallDistance, 1e-3f) << x << "," << y;
            EXPECT_EQ(exr.floats.at("normal.X")[i], 0.0f);
            EXPECT_EQ(exr.floats.at("normal.Y")[i], 0.0f);
            EXPECT_EQ(exr.floats.at("normal.Z")[i], 1.0f);   // towards the camera
            EXPECT_NEAR(exr.floats.at("albedo.R")[i], kWallAlbedo.x, 1e-3f);
            EXPECT_NEAR(exr.floats.at("albedo.G")[i], kWallAlbedo.y, 1e-3f);
            EXPECT_NEAR(exr.floats.at("albedo.B")[i], kWallAlbedo.z, 1e-3f);
            const Vec3f p{exr.floats.at("position.X")[i], exr.floats.at("position.Y")[i], exr.floats.at("position.Z")[i]};
            EXPECT_NEAR(p.z, 0.0f, 1e-3f);
            EXPECT_NEAR(dot(p - camera.position, camera.forward), kWallDistance, 1e-3f);
            // The pixel's centre ray, within half a pixel's footprint on the wall.
            const Ray centre = camera.generateRay((float(x) + 0.5f) / kWidth, (float(y) + 0.5f) / kHeight);
            const Vec3f onWall = centre.origin + centre.dir * (kWallDistance / dot(centre.dir, camera.forward));
            const float footprint = 2.0f * kWallDistance * camera.tanHalfFovY / kHeight;
            EXPECT_NEAR(p.x, onWall.x, footprint / 2);
            EXPECT_NEAR(p.y, onWall.y, footprint / 2);
            EXPECT_EQ(exr.uints.at("id.object")[i], kWallObject);
            EXPECT_EQ(exr.uints.at("id.part")[i], uint32_t(kWallPart));
            EXPECT_EQ(exr.uints.at("samples")[i], kSpp);
            EXPECT_EQ(exr.floats.at("A")[i], 1.0f);
        }
    }
    EXPECT_GT(wallPixels, 300);
}

TEST(FilmExr, SkyPixels) {
    const ExrRead exr = readExr(renderWallExr("sky.exr", false, 0.0f));
    for (uint32_t y = 0; y < kHeight; ++y) {
        if (!skyRow(y)) continue;
        for (uint32_t x = 0; x < kWidth; ++x) {
            const size_t i = size_t(y) * kWidth + x;
            EXPECT_TRUE(std::isinf(exr.floats.at("depth.Z")[i]) && exr.floats.at("depth.Z")[i] > 0);
            for (const char* zero : {"albedo.R", "normal.Z", "position.X", "position.Y", "position.Z"})
                EXPECT_EQ(exr.floats.at(zero)[i], 0.0f) << zero;
            EXPECT_EQ(exr.uints.at("id.object")[i], kSkyId);
            EXPECT_EQ(exr.uints.at("id.part")[i], kSkyId);
            EXPECT_EQ(exr.uints.at("samples")[i], kSpp);
            // The uniform sky itself.
            EXPECT_NEAR(exr.floats.at("B")[i], 1.0f, 1e-3f);
        }
    }
}

TEST(FilmExr, ColourIsTheMeanRadianceScaledByTheExposure) {
    Film film;
    const ExrRead exr = readExr(renderWallExr("colour.exr", true, 1.5f, &film));
    const LinearImage mean = meanRadiance(film);
    const float scale = std::exp2(1.5f);
    for (size_t i = 0; i < mean.pixels.size(); ++i) {
        EXPECT_EQ(exr.floats.at("R")[i], mean.pixels[i].x * scale);
        EXPECT_EQ(exr.floats.at("G")[i], mean.pixels[i].y * scale);
        EXPECT_EQ(exr.floats.at("B")[i], mean.pixels[i].z * scale);
    }
    const ExrRead halves = readExr(renderWallExr("colour_half.exr", false, 1.5f));
    for (size_t i = 0; i < mean.pixels.size(); ++i)
        EXPECT_EQ(halves.floats.at("G")[i], float(Imath::half(mean.pixels[i].y * scale)));
}
