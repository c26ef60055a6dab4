// The terrain from the command line: --terrain fbm renders and counts its bytes, a DEM GDAL cannot
// open is one line and exit 1, and bench --terrain-accuracy writes its measures.
#include "cli_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

using namespace urbis::test;

TEST(TerrainCli, FbmTerrainRendersAndItsBytesAreCounted) {
    const auto dir = scratchDir("terrain_fbm");
    const CommandResult r = runUrbis("render --terrain fbm --buildings 20 --width 48 --height 27 --spp 1 --stats s.json", dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json stats = nlohmann::json::parse(readFile(dir / "s.json"));
    EXPECT_GT(stats["bytes_by_kind"]["terrain"].get<size_t>(), size_t(4) * 2000 * 2000);
    EXPECT_EQ(stats["scene"]["terrain"]["kind"], "fbm");
}

TEST(TerrainCli, ADemGdalCannotOpenIsOneLineAndExitOne) {
    const auto dir = scratchDir("terrain_bad_dem");
    std::ofstream(dir / "bad.tif") << "not a raster";
    const CommandResult r = runUrbis("render --dem bad.tif --buildings 5 --width 16 --height 16 --spp 1", dir);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(r.err, "urbis: bad.tif: GDAL cannot open it as a raster\n");
    EXPECT_FALSE(std::filesystem::exists(dir / "urbis.png"));
}

TEST(TerrainCli, UnknownMarchIsAUsageError) {
    const auto dir = scratchDir("terrain_bad_march");
    EXPECT_EQ(runUrbis("render --terrain fbm --terrain-march fast --width 16 --height 16", dir).exitCode, 2);
}

TEST(TerrainCli, BenchTerrainAccuracyWritesEveryMeasure) {
    const auto dir = scratchDir("terrain_bench");
    const CommandResult r = runUrbis("bench --terrain-accuracy --device cpu --repeats 1 --width 64 --height 36 --json a.json", dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json a = nlohmann::json::parse(readFile(dir / "a.json"));
    for (const char* march : {"hierarchy", "lei"})
        for (const char* key : {"missed_intersections", "mean_hde_m", "max_hde_m", "mean_ide_m", "median_ms"})
            EXPECT_TRUE(a["methods"][march].contains(key)) << march << " " << key;
    EXPECT_EQ(a["methods"]["hierarchy"]["missed_intersections"], 0);
    EXPECT_LT(a["methods"]["hierarchy"]["max_hde_m"].get<double>(), 0.01);
    // HDE by the hits' distance: four bands, the first within 1 km, whose hits add up to all of them.
    const nlohmann::json& bands = a["methods"]["hierarchy"]["hde_by_distance"];
    ASSERT_EQ(bands.size(), 4u);
    EXPECT_EQ(bands[0]["from_m"], 0.0);
    EXPECT_EQ(bands[0]["to_m"], 1000.0);
    EXPECT_TRUE(bands[3]["to_m"].is_null()) << "the last band runs to the horizon";
    size_t hits = 0;
    for (const nlohmann::json& band : bands) {
        hits += band["hits"].get<size_t>();
        EXPECT_LE(band["max_hde_m"].get<double>(), a["methods"]["hierarchy"]["max_hde_m"].get<double>());
    }
    EXPECT_EQ(hits, a["methods"]["hierarchy"]["hits"].get<size_t>());
}

TEST(TerrainCli, CameraGeoAltitudeAboveGroundIsTheAglSuffix) {
    const std::string village = URBIS_OSMNX_DATA "/planet_10.068,48.135_10.071,48.137.osm";
    if (!std::filesystem::exists(village)) GTEST_SKIP() << village << " is absent (Debian's python-osmnx-doc)";
    const auto dir = scratchDir("terrain_camera_agl");
    const std::string render = "render --osm '" + village + "' --terrain fbm --width 16 --height 9 --spp 1 ";
    const CommandResult r = runUrbis(render + "--camera-geo 10.0695,48.136,30agl,0,-20 --save-scene s.json", dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json scene = nlohmann::json::parse(readFile(dir / "s.json"));
    EXPECT_EQ(scene["camera"]["geo"]["above_ground"], true);
    EXPECT_EQ(scene["camera"]["geo"]["altitude"], 30.0);
    EXPECT_EQ(runUrbis(render + "--camera-geo 10.0695,48.136,30m,0,-20", dir).exitCode, 2);
}
