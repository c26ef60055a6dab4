#include "osm/osm_import.h"

#include "base/input_error.h"
#include "osm/building_palette.h"
#include "osm/city_builder.h"
#include "osm/height_estimate.h"
#include "osm/osm_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace urbis {

namespace {

constexpr double kExtentPadding = 1e-6; // degrees, about 0.1 m

[[noreturn]] void fail(const std::string& path, std::string problem, FailureKind kind = FailureKind::BadInput) {
    std::replace_if(problem.begin(), problem.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
    throw InputError(path + ": " + problem, kind);
}

void checkOptions(const std::string& path, const ImportOptions& options) {
    if (const auto& range = options.untaggedHeightRange;
        range && !((*range)[0] > 0.0f && (*range)[0] <= (*range)[1] && (*range)[1] <= 1000.0f))
        fail(path, "building height range must satisfy 0 < min <= max <= 1000 m", FailureKind::Usage);
    if (!(options.metresPerLevel > 0.0f && options.metresPerLevel < 20.0f))
        fail(path, "metres per level must lie in (0, 20)", FailureKind::Usage);
    if (options.bbox) {
        const auto [w, s, e, n] = *options.bbox;
        if (!(w >= -180.0 && w < e && e <= 180.0 && s >= -90.0 && s < n && n <= 90.0))
            fail(path, "bbox must be minLon,minLat,maxLon,maxLat with min < max, in degrees", FailureKind::Usage);
    }
}

void checkReadable(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) fail(path, "no such file");
    if (!std::filesystem::is_regular_file(path, ec)) fail(path, "not a regular file");
    if (!std::ifstream(path, std::ios::binary)) fail(path, "cannot open file for reading");
    if (std::filesystem::file_size(path, ec) == 0) fail(path, "empty file");
}

} // namespace

CityModel importOsm(const std::string& path, const ImportOptions& options) {
    checkOptions(path, options);
    checkReadable(path);
    RawFeatures raw;
    try {
        raw = readOsm(path, options);
    } catch (const std::exception& e) {
        fail(path, std::string("cannot read OSM data: ") + e.what());
    }
    const GeoBox header = raw.headerBox;
    GeoBox box = header;
    const char* boxSource = "header";
    if (options.bbox) {
        box = {(*options.bbox)[0], (*options.bbox)[1], (*options.bbox)[2], (*options.bbox)[3]};
        boxSource = "bbox";
    } else if (!box.valid()) {
        const GeoBox& e = raw.dataExtent; // padded, so that a single node or a meridian gives a box
        if (e.minLon > e.maxLon) fail(path, "no nodes with locations");
        box = {e.minLon - kExtentPadding, e.minLat - kExtentPadding, e.maxLon + kExtentPadding, e.maxLat + kExtentPadding};
        boxSource = "data_extent";
    }

    CityModel city = buildCityModel(std::move(raw), box);
    if (header.valid()) city.headerBox = {true, header.minLon, header.minLat, header.maxLon, header.maxLat};
    city.cropBox = {true, box.minLon, box.minLat, box.maxLon, box.maxLat};
    city.cropBoxSource = boxSource;
    if (city.buildings.empty())
        fail(path, "no buildings inside the box (" + std::to_string(box.minLon) + "," + std::to_string(box.minLat) +
                       "," + std::to_string(box.maxLon) + "," + std::to_string(box.maxLat) + ")");
    // Both need the whole city: its region and, for heights, each building's tagged neighbours.
    paintUntaggedBuildings(city);
    estimateHeights(city, options);
    city.source = std::filesystem::path(path).filename().string();
    for (const std::string& w : city.warnings) std::fprintf(stderr, "urbis: warning: %s: %s\n", path.c_str(), w.c_str());
    return city;
}

} // namespace urbis
