// Film files by extension: PNG pixels as before the film existed, errors as one line naming the file.
#include "film/film_output.h"
#include "base/input_error.h"
#include "png_support.h"
#include "process_scratch_dir.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace urbis;
using urbis::test::processScratchDir;

namespace {

std::string readBytes(const std::filesystem::path& path) {
    std::ifstream f(path, std::ios::binary);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
}

/// The film of tests/film_reference/gradient_64x16.png: three samples per pixel whose sums span
/// sixteen stops, so that every part of the tone curve shows.
Film gradientFilm() {
    Film film(64, 16, false);
    for (uint32_t y = 0; y < 16; ++y)
        for (uint32_t x = 0; x < 64; ++x) {
            film.arrays.radianceSum[y * 64 + x] = Vec3f{std::exp2(float(x) / 4.0f - 8.0f), float(y) * 0.37f,
                                                        float((x * 7 + y * 13) % 23) * 0.11f};
            film.arrays.sampleCount[y * 64 + x] = 3;
        }
    return film;
}

/// Expects `write` to throw one line of `kind` that names `path`, and no file left at `path` + ".tmp".
template <class Write>
void expectOneLineError(Write write, const std::string& path, FailureKind kind) {
    try {
        write();
        ADD_FAILURE() << "no error for " << path;
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find(path), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        EXPECT_EQ(int(e.kind()), int(kind)) << message;
    }
    EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
}

} // namespace

// The reference was written by the renderer before it kept a film (LinearImage of sum / 3, toneMap
// at -0.6 EV, writePng): the same mean and curve give the same pixels (the encoder's level has changed
// since, so the compressed bytes differ).
TEST(FilmOutput, PngPixelsAsBeforeTheFilm) {
    const std::filesystem::path path = processScratchDir() / "gradient.png";
    writeFilm(gradientFilm(), path.string(), FilmOutputOptions{-0.6f, false});
    const test::Rgb reference = test::readRgbPng(std::filesystem::path(URBIS_FILM_REFERENCE) / "gradient_64x16.png");
    const test::Rgb written = test::readRgbPng(path);
    ASSERT_EQ(reference.pixels.size(), 64u * 16u * 3u);
    EXPECT_EQ(written.width, 64u);
    EXPECT_EQ(written.height, 16u);
    EXPECT_TRUE(written.pixels == reference.pixels) << "the PNG of a film changed";
}

TEST(FilmOutput, FormatFollowsTheExtension) {
    EXPECT_EQ(filmFormatOf("a/b.png"), FilmFormat::Png);
    EXPECT_EQ(filmFormatOf("B.PNG"), FilmFormat::Png);
    EXPECT_EQ(filmFormatOf("c.Exr"), FilmFormat::Exr);
    EXPECT_TRUE(filmOutputNeedsAovs("c.exr"));
    EXPECT_FALSE(filmOutputNeedsAovs("c.png"));
    const Film film = gradientFilm();
    for (const char* name : {"out.tiff", "out.jpg", "out"}) {
        const std::string path = (processScratchDir() / name).string();
        expectOneLineError([&] { writeFilm(film, path, {}); }, path, FailureKind::Usage);
        EXPECT_FALSE(std::filesystem::exists(path));
    }
}

TEST(FilmOutput, UnwritablePathsFailWithOneLine) {
    const Film film = gradientFilm();
    for (const char* name : {"x.png", "x.exr"}) {
        const std::string missingFolder = (processScratchDir() / "no_such_folder" / name).string();
        expectOneLineError([&] { writeFilm(film, missingFolder, {}); }, missingFolder, FailureKind::Output);
        // A folder in the way of the rename: the temporary is written, then removed.
        const std::filesystem::path folder = processScratchDir() / (std::string("folder_") + name);
        std::filesystem::create_directories(folder / "inside");
        expectOneLineError([&] { writeFilm(film, folder.string(), {}); }, folder.string(), FailureKind::Output);
        EXPECT_TRUE(std::filesystem::is_directory(folder / "inside"));
    }
}

TEST(FilmOutput, ExrWithoutAovsHasColourOnly) {
    const std::filesystem::path path = processScratchDir() / "colour_only.exr";
    writeFilm(gradientFilm(), path.string(), {});
    EXPECT_EQ(readBytes(path).substr(0, 4), std::string("\x76\x2f\x31\x01", 4));   // the EXR magic number
}
