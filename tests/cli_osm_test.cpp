// `urbis render --osm` and `urbis inspect` end to end on real extracts and on broken files.
#include "cli_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <map>
#include <random>
#include <regex>
#include <set>

using namespace urbis::test;
namespace fs = std::filesystem;

namespace {

const std::string kVillage = URBIS_OSMNX_DATA "/planet_10.068,48.135_10.071,48.137.osm";

void writeFile(const fs::path& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

/// A broken input file: non-zero exit, one line naming the file, no image or stats left behind.
void expectBadInput(const fs::path& dir, const std::string& file) {
    CommandResult r = runUrbis("render --width 32 --height 32 --spp 1 --osm '" + file + "' --out out.png --stats s.json", dir);
    EXPECT_NE(r.exitCode, 0) << file;
    EXPECT_NE(r.err.find(fs::path(file).filename().string()), std::string::npos) << "message must name the file: " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "not one line: " << r.err;
    for (const char* name : {"out.png", "out.png.tmp", "s.json", "s.json.tmp"})
        EXPECT_FALSE(fs::exists(dir / name)) << name << " left behind for " << file;
    CommandResult inspect = runUrbis("inspect '" + file + "'", dir);
    EXPECT_NE(inspect.exitCode, 0) << file;
}

std::string osmXml(const std::string& body) {
    return "<?xml version='1.0' encoding='UTF-8'?>\n<osm version='0.6' generator='test'>\n"
           "<bounds minlat='48.0' minlon='10.0' maxlat='48.01' maxlon='10.01'/>\n" + body + "</osm>\n";
}

/// A square building way (ids from `id`) about 20 m wide near (10.005, 48.005) with extra tags.
std::string squareBuilding(int id, const std::string& tags, double lonOffset = 0) {
    std::string nodes, refs;
    double lon[4] = {10.005, 10.00527, 10.00527, 10.005}, lat[4] = {48.005, 48.005, 48.00518, 48.00518};
    for (int i = 0; i < 4; ++i) {
        nodes += "<node id='" + std::to_string(id * 10 + i) + "' lat='" + std::to_string(lat[i]) + "' lon='" +
                 std::to_string(lon[i] + lonOffset) + "'/>\n";
        refs += "<nd ref='" + std::to_string(id * 10 + i) + "'/>";
    }
    return nodes + "<way id='" + std::to_string(id) + "'>" + refs + "<nd ref='" + std::to_string(id * 10) +
           "'/><tag k='building' v='yes'/>" + tags + "</way>\n";
}

} // namespace

TEST(CliOsm, RendersTheBavarianVillage) {
    auto dir = scratchDir("village");
    CommandResult r = runUrbis("render --osm '" + kVillage + "' --width 80 --height 60 --spp 2 --stats s.json", dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto stats = nlohmann::json::parse(readFile(dir / "s.json"));
    EXPECT_GT(stats["counts"]["buildings"].get<int>(), 10);
    EXPECT_TRUE(fs::exists(dir / "urbis.png"));
}

TEST(CliOsm, UntaggedHeightsAreEstimatedUnlessARangeIsGiven) {
    // The village: 22 of 31 buildings untagged, its tagged ones 6 m (docs/heights.md).
    auto dir = scratchDir("height_range");
    const auto meanHeight = [&dir](const std::string& extra) {
        CommandResult r = runUrbis("render --osm '" + kVillage + "' --width 16 --height 16 --spp 1 --stats s.json " + extra, dir);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        return nlohmann::json::parse(readFile(dir / "s.json"))["counts"]["mean_building_height"].get<double>();
    };
    EXPECT_LT(meanHeight(""), 10.0);
    EXPECT_GT(meanHeight("--building-height-range 20:100"), 30.0);
    CommandResult help = runUrbis("render --help", dir);
    EXPECT_NE(help.out.find("heights are estimated"), std::string::npos) << help.out;
}

TEST(CliOsm, InspectJsonHasTheDocumentedKeys) {
    auto dir = scratchDir("inspect");
    CommandResult r = runUrbis("inspect --json '" + kVillage + "'", dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto j = nlohmann::json::parse(r.out);
    for (const char* key : {"buildings", "building_parts", "roads", "lamps", "trees", "dropped"})
        EXPECT_TRUE(j.contains(key)) << key;
    EXPECT_GT(j["buildings"].get<int>(), 10);
    EXPECT_GT(j["roads"].get<int>(), 0);
    int heights = 0;
    for (const char* key : {"from_height_tag", "from_levels", "from_nearby_median", "from_type_table", "from_range"})
        heights += j["heights"].at(key).get<int>();
    EXPECT_EQ(heights, j["buildings"].get<int>());
    EXPECT_EQ(j["heights"]["from_range"], 0); // estimated: inspect takes no --building-height-range
}

TEST(CliOsm, BrokenFilesGiveOneLineAndNoOutput) {
    auto dir = scratchDir("broken");
    expectBadInput(dir, (dir / "missing.osm.pbf").string());
    writeFile(dir / "empty.osm", "");
    expectBadInput(dir, (dir / "empty.osm").string());
    writeFile(dir / "malformed.osm", "<?xml version='1.0'?>\n<osm version='0.6'><node id='1' lat='48.0' lon=");
    expectBadInput(dir, (dir / "malformed.osm").string());
    std::mt19937 rng(7);
    std::string noise(4096, '\0');
    for (char& c : noise) c = char(rng());
    writeFile(dir / "noise.osm.pbf", noise);
    expectBadInput(dir, (dir / "noise.osm.pbf").string());
    writeFile(dir / "noise.osm.bz2", noise);
    expectBadInput(dir, (dir / "noise.osm.bz2").string());
    fs::path shared = URBIS_SHARED_DATA "/moscow_center_2020.osm.pbf";
    if (fs::exists(shared)) {
        std::string whole = readFile(shared);
        writeFile(dir / "truncated.osm.pbf", whole.substr(0, whole.size() / 2));
        expectBadInput(dir, (dir / "truncated.osm.pbf").string());
    } else {
        std::cout << "note: the truncated-PBF case needs " << shared << ", not found; tests/osm_bad_input_test.cpp covers it\n";
    }
    fs::path dirAsFile = dir / "folder.osm";
    fs::create_directories(dirAsFile);
    expectBadInput(dir, dirAsFile.string());
}

TEST(CliOsm, NothingInTheBoxIsAnError) {
    auto dir = scratchDir("empty_box");
    writeFile(dir / "far.osm", osmXml(squareBuilding(1, "", 5.0)));  // 5 degrees east of the box
    expectBadInput(dir, (dir / "far.osm").string());
}

TEST(CliOsm, AbsurdTagsDropOrRepairOneBuildingNotTheRender) {
    auto dir = scratchDir("absurd");
    std::string body = squareBuilding(1, "<tag k='height' v='-5'/>") +
                       squareBuilding(2, "<tag k='height' v='1e30'/>", 0.001) +
                       squareBuilding(3, "<tag k='height' v='NaN'/>", 0.002) +
                       squareBuilding(4, "<tag k='building:levels' v='-3'/>", 0.003) +
                       squareBuilding(5, "<tag k='height' v='12 m'/>", 0.004);
    // A self-intersecting bow-tie and a degenerate two-node way.
    body += "<node id='901' lat='48.006' lon='10.006'/><node id='902' lat='48.0062' lon='10.0063'/>"
            "<node id='903' lat='48.006' lon='10.0063'/><node id='904' lat='48.0062' lon='10.006'/>\n"
            "<way id='90'><nd ref='901'/><nd ref='902'/><nd ref='903'/><nd ref='904'/><nd ref='901'/>"
            "<tag k='building' v='yes'/></way>\n"
            "<way id='91'><nd ref='901'/><nd ref='902'/><nd ref='901'/><tag k='building' v='yes'/></way>\n";
    writeFile(dir / "absurd.osm", osmXml(body));
    CommandResult r = runUrbis("inspect --json absurd.osm", dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto j = nlohmann::json::parse(r.out);
    EXPECT_GE(j["buildings"].get<int>(), 5);
    EXPECT_FALSE(j["dropped"].empty()) << r.out;
    CommandResult render = runUrbis("render --osm absurd.osm --width 32 --height 32 --spp 1", dir);
    EXPECT_EQ(render.exitCode, 0) << render.err;
}

TEST(CliOsm, CameraInsideABuildingWarnsOrFailsWithStrict) {
    auto dir = scratchDir("camera_inside");
    // The box's centre, the local origin, is the building's south-west corner: it covers x 0..20 m, z -20..0.
    writeFile(dir / "tower.osm", osmXml(squareBuilding(7, "<tag k='height' v='30'/>")));
    const std::string render = "render --osm tower.osm --width 32 --height 32 --spp 1 --out out.png ";
    CommandResult inside = runUrbis(render + "--camera 10,5,-10,100,5,-100", dir);
    EXPECT_EQ(inside.exitCode, 0) << inside.err;
    EXPECT_NE(inside.err.find("urbis: warning: the camera (10.0, 5.0, -10.0) is inside a building (way 7)"),
              std::string::npos) << inside.err;
    CommandResult above = runUrbis(render + "--camera 10,40,-10,100,0,-100", dir);
    EXPECT_EQ(above.err, "") << "above the roof is not inside";
    fs::remove(dir / "out.png");
    CommandResult strict = runUrbis(render + "--strict --camera 10,5,-10,100,5,-100", dir);
    EXPECT_EQ(strict.exitCode, 2) << strict.err;
    EXPECT_FALSE(fs::exists(dir / "out.png"));
}

namespace {

/// `inspect --json --ids` of `file` run in `dir`, parsed; fails the test on a non-zero exit.
nlohmann::json inspectIds(const fs::path& dir, const std::string& file) {
    CommandResult r = runUrbis("inspect --json --ids '" + file + "'", dir);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return r.exitCode == 0 ? nlohmann::json::parse(r.out) : nlohmann::json::object();
}

/// Buildings are kept by centroid, so the kept geometry may reach this far (degrees) past the box.
constexpr double kStraddle = 0.005;

/// The kept bounds lie in the header box (up to buildings that straddle it), which is the crop box.
void expectBoundsInHeaderBox(const nlohmann::json& j) {
    const nlohmann::json& b = j["bounds"];
    ASSERT_FALSE(b["header"].is_null()) << "the file has a header box";
    EXPECT_EQ(b["crop_source"], "header");
    EXPECT_EQ(b["crop"], b["header"]);
    EXPECT_GE(b["kept"]["min_lon"].get<double>(), b["header"]["min_lon"].get<double>() - kStraddle);
    EXPECT_GE(b["kept"]["min_lat"].get<double>(), b["header"]["min_lat"].get<double>() - kStraddle);
    EXPECT_LE(b["kept"]["max_lon"].get<double>(), b["header"]["max_lon"].get<double>() + kStraddle);
    EXPECT_LE(b["kept"]["max_lat"].get<double>(), b["header"]["max_lat"].get<double>() + kStraddle);
    EXPECT_LT(b["kept"]["min_lon"].get<double>(), b["kept"]["max_lon"].get<double>());
    EXPECT_LT(b["kept"]["min_lat"].get<double>(), b["kept"]["max_lat"].get<double>());
}

/// Every reason lists ids (n/w/r + digits), no more than its count; no repaired object is also dropped.
void expectIdsPerReason(const nlohmann::json& j) {
    std::set<std::string> dropped;
    for (const char* map : {"dropped", "repaired"})
        for (const auto& [reason, count] : j[map].items()) {
            const nlohmann::json& ids = j[std::string(map) + "_ids"][reason];
            EXPECT_GT(ids.size(), 0u) << map << " " << reason;
            EXPECT_LE(ids.size(), count.get<size_t>()) << map << " " << reason;
            for (const nlohmann::json& id : ids) {
                EXPECT_TRUE(std::regex_match(id.get<std::string>(), std::regex("[nwr][0-9]+"))) << id;
                if (std::string(map) == "dropped") dropped.insert(id.get<std::string>());
                else EXPECT_FALSE(dropped.contains(id.get<std::string>())) << id << " is both repaired and dropped";
            }
        }
    for (const char* repair : {"made_valid", "repaired", "bad_height_tag", "bad_levels_tag"})
        EXPECT_FALSE(j["dropped"].contains(repair)) << repair << " is a repair, not a drop";
}

} // namespace

TEST(CliOsm, InspectKeptBoundsLieInTheHeaderBox) {
    auto dir = scratchDir("inspect_bounds");
    for (const std::string& file : {kVillage, std::string(URBIS_OSMNX_DATA "/West-Oakland.osm.bz2")})
        expectBoundsInHeaderBox(inspectIds(dir, file));
    for (const char* name : {"sf_downtown_2023.osm.pbf", "london_city_2020.osm.pbf", "moscow_center_2020.osm.pbf"}) {
        const fs::path shared = fs::path(URBIS_SHARED_DATA) / name;
        if (!fs::exists(shared)) {
            std::cout << "note: skipping " << shared << " (not found)\n";
            continue;
        }
        const nlohmann::json j = inspectIds(dir, shared.string());
        expectBoundsInHeaderBox(j);
        expectIdsPerReason(j);
    }
    const nlohmann::json cropped = nlohmann::json::parse(
        runUrbis("inspect --json --bbox 10.069,48.135,10.070,48.136 '" + kVillage + "'", dir).out);
    EXPECT_EQ(cropped["bounds"]["crop_source"], "bbox");
    EXPECT_DOUBLE_EQ(cropped["bounds"]["crop"]["min_lon"].get<double>(), 10.069);
}

TEST(CliOsm, InspectIdsExistInTheFileAndRepairsAreNotDrops) {
    auto dir = scratchDir("inspect_ids");
    const nlohmann::json j = inspectIds(dir, kVillage);
    expectIdsPerReason(j);
    EXPECT_GT(j["dropped"].size(), 0u);
    EXPECT_GT(j["repaired"].size(), 0u);
    const std::string xml = readFile(kVillage);
    const std::map<char, std::string> element{{'n', "node"}, {'w', "way"}, {'r', "relation"}};
    for (const char* map : {"dropped_ids", "repaired_ids"})
        for (const auto& [reason, ids] : j[map].items())
            for (const nlohmann::json& id : ids) {
                const std::string name = id.get<std::string>();
                const std::string tag = "<" + element.at(name[0]) + " id=\"" + name.substr(1) + "\"";
                EXPECT_NE(xml.find(tag), std::string::npos) << reason << ": " << name << " is not in the file";
            }
    expectIdsPerReason(inspectIds(dir, URBIS_OSMNX_DATA "/West-Oakland.osm.bz2"));
    CommandResult text = runUrbis("inspect --ids '" + kVillage + "'", dir);
    ASSERT_EQ(text.exitCode, 0);
    for (const char* line : {"  dropped:\n", "  repaired:\n", "  dropped_ids:\n", "crop_source", "10.068"})
        EXPECT_NE(text.out.find(line), std::string::npos) << line << " in\n" << text.out;
}

TEST(CliOsm, EveryReasonIsDocumented) {
    auto dir = scratchDir("reasons_documented");
    const std::string docs = readFile(URBIS_EXAMPLES "/../cli.md");
    ASSERT_FALSE(docs.empty());
    std::string body = squareBuilding(1, "<tag k='height' v='tall'/><tag k='building:levels' v='many'/>") +
                       squareBuilding(2, "<tag k='roof:colour' v='sparkly'/>", 5.0);
    writeFile(dir / "reasons.osm", osmXml(body));
    for (const std::string& file : {kVillage, std::string(URBIS_OSMNX_DATA "/West-Oakland.osm.bz2"),
                                   (dir / "reasons.osm").string()}) {
        CommandResult r = runUrbis("render --width 16 --height 16 --spp 1 --osm '" + file + "' --stats s.json --out o.png", dir);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const nlohmann::json stats = nlohmann::json::parse(readFile(dir / "s.json"));
        for (const char* map : {"dropped", "repaired"})
            for (const auto& [reason, n] : stats[map].items()) {
                const std::string prefixless = reason.rfind("part_", 0) == 0 ? reason.substr(5)
                                               : reason.rfind("area_", 0) == 0 ? reason.substr(5) : reason;
                EXPECT_NE(docs.find("`" + prefixless + "`"), std::string::npos) << reason << " is not in docs/cli.md";
            }
    }
}
