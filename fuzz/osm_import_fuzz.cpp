// libFuzzer target: bytes -> an OSM file (XML or PBF, sniffed from the bytes) -> importOsm ->
// meshCity, the path `urbis render --osm` takes before rendering. InputError is the clean answer
// to bad input; anything else (another exception, a crash, a sanitizer report) is a finding.
#include "citygen/city_mesher.h"
#include "base/input_error.h"
#include "osm/osm_import.h"

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

namespace {

/// A PBF file opens with a BlobHeader (4-byte length, then a protobuf whose first field is the
/// type "OSMHeader"); everything else goes to the XML parser.
bool looksLikePbf(std::string_view bytes) { return bytes.substr(0, 32).find("OSMHeader") != std::string_view::npos; }

/// libosmium reads files and picks the format from the name, as urbis does: one file per
/// process, rewritten for each input.
std::string inputPath(bool pbf) {
    static const std::string stem =
        (std::filesystem::temp_directory_path() / ("urbis_fuzz_" + std::to_string(getpid()))).string();
    return stem + (pbf ? ".osm.pbf" : ".osm");
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    const std::string path = inputPath(looksLikePbf(bytes));
    std::ofstream(path, std::ios::binary | std::ios::trunc).write(bytes.data(), std::streamsize(bytes.size()));
    try {
        const urbis::CityModel city = urbis::importOsm(path, {});
        (void)urbis::meshCity(city);
    } catch (const urbis::InputError&) {
    }
    std::remove(path.c_str());
    return 0;
}
