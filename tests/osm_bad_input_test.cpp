// Bad input files: each must give one InputError line that names the file.
#include "base/input_error.h"
#include "osm/osm_import.h"

#include "process_scratch_dir.h"

#include <gtest/gtest.h>
#include <osmium/io/any_input.hpp>
#include <osmium/io/any_output.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>

#include <unistd.h>

using namespace urbis;

namespace {

const std::string kVillage = URBIS_OSMNX_DATA "/planet_10.068,48.135_10.071,48.137.osm";

using test::processScratchDir;

std::string tempPath(const std::string& name) { return (processScratchDir() / name).string(); }

std::string writeBytes(const std::string& name, const std::string& bytes) {
    const std::string path = tempPath(name);
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
}

/// The village converted to PBF with libosmium's writer: a real PBF that is always there.
std::string villagePbf() {
    const std::string path = tempPath("village.osm.pbf");
    osmium::io::Reader reader{kVillage};
    osmium::io::Writer writer{path, reader.header(), osmium::io::overwrite::allow};
    while (osmium::memory::Buffer buffer = reader.read()) writer(std::move(buffer));
    writer.close();
    reader.close();
    return path;
}

/// Imports `path` and returns the InputError's message; fails the test if none is thrown.
std::string importError(const std::string& path, const ImportOptions& options = {}) {
    try {
        importOsm(path, options);
    } catch (const InputError& e) {
        return e.what();
    }
    ADD_FAILURE() << "no InputError for " << path;
    return {};
}

void expectOneLineNaming(const std::string& message, const std::string& path, const char* problem) {
    EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_NE(message.find(problem), std::string::npos) << message;
}

} // namespace

TEST(OsmBadInput, ConvertedPbfImportsLikeTheXml) {
    EXPECT_EQ(importOsm(villagePbf(), {}).buildings.size(), importOsm(kVillage, {}).buildings.size());
}

TEST(OsmBadInput, TruncatedPbf) {
    std::ifstream in(villagePbf(), std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(in), {}};
    ASSERT_GT(bytes.size(), 1000u);
    const std::string path = writeBytes("truncated.osm.pbf", bytes.substr(0, bytes.size() / 2));
    expectOneLineNaming(importError(path), path, "cannot read OSM data");
}

TEST(OsmBadInput, RandomBytes) {
    std::mt19937 random(42);
    std::string bytes(8192, '\0');
    for (char& c : bytes) c = char(random() & 0xff);
    const std::string path = writeBytes("random.osm.pbf", bytes);
    expectOneLineNaming(importError(path), path, "cannot read OSM data");
}

TEST(OsmBadInput, MalformedXml) {
    const std::string path = writeBytes("malformed.osm", "<?xml version='1.0'?>\n<osm version='0.6'>\n"
                                                         "<node id='1' lat='50' lon='10'><tag k='a' v=\n");
    expectOneLineNaming(importError(path), path, "cannot read OSM data");
}

TEST(OsmBadInput, EmptyFile) {
    const std::string path = writeBytes("empty.osm", "");
    expectOneLineNaming(importError(path), path, "empty file");
}

TEST(OsmBadInput, MissingFile) {
    const std::string path = tempPath("does-not-exist.osm.pbf");
    expectOneLineNaming(importError(path), path, "no such file");
}

TEST(OsmBadInput, UnknownFormat) {
    const std::string path = writeBytes("notes.txt", "hello\n");
    expectOneLineNaming(importError(path), path, "cannot read OSM data");
}

TEST(OsmBadInput, BoxWithoutBuildings) {
    ImportOptions options;
    options.bbox = std::array<double, 4>{10.0, 48.0, 10.001, 48.001}; // fields south of the village
    expectOneLineNaming(importError(kVillage, options), kVillage, "no buildings");
    const std::string roadsOnly = writeBytes(
        "roads-only.osm", "<?xml version='1.0'?>\n<osm version='0.6'>\n"
                          "<node id='1' version='1' lat='50' lon='10'/><node id='2' version='1' lat='50.001' lon='10'/>\n"
                          "<way id='3' version='1'><nd ref='1'/><nd ref='2'/><tag k='highway' v='residential'/></way>\n"
                          "</osm>\n");
    expectOneLineNaming(importError(roadsOnly), roadsOnly, "no buildings");
}

TEST(OsmBadInput, BadOptions) {
    ImportOptions options;
    options.untaggedHeightRange = {{50.0f, 10.0f}};
    expectOneLineNaming(importError(kVillage, options), kVillage, "height range");
    options = {};
    options.bbox = std::array<double, 4>{10.1, 48.0, 10.0, 48.1}; // west > east
    expectOneLineNaming(importError(kVillage, options), kVillage, "bbox");
}
