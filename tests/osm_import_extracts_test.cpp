// Real OSM extracts: counts checked against what osmium-tool says about the same files.
//
// Reference counts (osmium-tool 1.15, see /work/shared/data/README.md):
//   total    = building ways + type=multipolygon relations with building != no:
//              osmium tags-filter -R FILE w/building r/type=multipolygon | tags-filter -R w/building r/building
//              | tags-filter -i -R wr/building=no
//   touching = the same after osmium extract -s complete_ways -b HEADER_BOX (objects with
//              any node in the box; the README's "inside the header box")
//   highways, lamps, trees: osmium tags-filter -R FILE w/highway | n/highway=street_lamp | n/natural=tree
//   highwayAreas: of those highways, the closed ways with area=yes (first node = last node in
//              the OPL of osmium tags-filter FILE w/highway): imported as pedestrian areas, not roads
// The importer keeps a building when its centroid lies in the box, so
// its "inside" count is below `touching` by the buildings that straddle the border; the
// tolerance below bounds that share per file (small boxes of big blocks lose the most).
#include "osm/osm_import.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <set>

using namespace urbis;

namespace {

struct Extract {
    const char* name;
    std::string path;
    bool required;        ///< always present (Debian's osmnx test data) or else skipped
    uint64_t total;       ///< building objects in the file
    uint64_t touching;    ///< building objects with a node in the box
    double straddling;    ///< tolerated share of `touching` whose centroid lies outside
    uint64_t highways, lamps, trees;
    uint64_t highwayAreas; ///< highways that are closed area=yes ways: areas, not roads
    uint64_t underground, partsUnderground; ///< isUnderground drops, each checked by its tags
};

const std::string kOsmnx = URBIS_OSMNX_DATA, kShared = URBIS_SHARED_DATA;

const Extract kExtracts[] = {
    // 33 buildings, one with 2 distinct nodes (degenerate); no box needed for the rest.
    {"Village", kOsmnx + "/planet_10.068,48.135_10.071,48.137.osm", true, 33, 33, 0.04, 19, 0, 0, 0, 0, 0},
    // 2 of 23 cross the box border with their centroid outside.
    {"WestOakland", kOsmnx + "/West-Oakland.osm.bz2", true, 23, 23, 0.09, 31, 0, 0, 0, 0, 0},
    // Underground: five BART/Muni station halls and a visitor centre (location=underground), a
    // car park (parking=underground), a cafe at level=-0.9; a concourse and two platform parts.
    {"SanFrancisco", kShared + "/sf_downtown_2023.osm.pbf", false, 7793, 7134, 0.02, 8553, 533, 2219, 114, 8, 3},
    // Underground: a basement pub (level=-1); 15 shops of a lower mall floor (level=-1 parts).
    {"London", kShared + "/london_city_2020.osm.pbf", false, 2155, 1812, 0.04, 3141, 131, 1078, 66, 1, 15},
    // 0.85 x 0.66 km box of large city blocks: 38 of 431 straddle. Its one underground
    // bunker lies outside the box.
    {"Moscow", kShared + "/moscow_center_2020.osm.pbf", false, 678, 431, 0.10, 1304, 31, 61, 5, 0, 0},
    // No header box: the data extent holds all; one relation lacks members; nine garage
    // parts at level=-1.
    {"Berlin", kShared + "/berlin_neukolln_2024.osm", false, 127, 127, 0.01, 211, 52, 145, 0, 0, 9},
    {"NewYork", kShared + "/nyc_queens_village_2016.osm.pbf", false, 50836, 50014, 0.01, 1956, 0, 0, 0, 0, 0},
};

/// Names the case in test output instead of dumping its bytes.
void PrintTo(const Extract& e, std::ostream* os) { *os << e.name; }

class OsmExtract : public testing::TestWithParam<Extract> {};

} // namespace

TEST_P(OsmExtract, CountsMatchOsmium) {
    const Extract& e = GetParam();
    if (!std::filesystem::exists(e.path)) {
        ASSERT_FALSE(e.required) << e.path << " is missing";
        GTEST_SKIP() << e.path << " not found, skipping";
    }
    // Import speed is a benchmark's business (bench/), not this test's: a loaded CI machine must not fail it.
    const CityModel city = importOsm(e.path, {});
    const nlohmann::json summary = inspectJson(city);
    RecordProperty("summary", summary.dump());
    std::cout << e.name << ": " << summary.dump() << "\n";

    // Every building object of the file is either kept (perhaps replaced by its parts) or
    // dropped for one reason. Not exact where a multipolygon has several outer rings (each
    // is counted) or a way is both building and building:part (counted as a part).
    const uint64_t outlines = city.buildings.size() - city.buildingParts() + countOf(city.dropped, "replaced_by_parts");
    uint64_t dropped = 0;
    for (const char* reason : {"outside_bbox", "incomplete_geometry", "unclosed_way", "degenerate_footprint",
                               "self_intersecting", "too_small", "invalid_multipolygon", "underground"})
        dropped += countOf(city.dropped, reason);
    EXPECT_NEAR(double(outlines + dropped), double(e.total), 0.005 * double(e.total));

    const uint64_t inside =
        outlines + countOf(city.dropped, "too_small") + countOf(city.dropped, "self_intersecting") + countOf(city.dropped, "underground");
    EXPECT_LE(inside, e.touching);
    EXPECT_GE(double(inside), double(e.touching) * (1.0 - e.straddling));

    std::set<int64_t> roadIds;
    for (const Road& r : city.roads) roadIds.insert(r.osmId);
    EXPECT_EQ(roadIds.size() + countOf(city.dropped, "road_outside_bbox") + countOf(city.dropped, "road_degenerate") +
                  countOf(city.dropped, "road_incomplete_geometry") + e.highwayAreas,
              e.highways);
    EXPECT_EQ(city.lamps.size() + countOf(city.dropped, "lamp_outside_bbox"), e.lamps);
    // Mapped trees (nodes; a tree_row way's trees are placed along it and not counted by osmium).
    const auto mapped = std::count_if(city.trees.begin(), city.trees.end(), [](const Tree& t) { return !t.inRow; });
    EXPECT_EQ(uint64_t(mapped) + countOf(city.dropped, "tree_outside_bbox"), e.trees);

    for (const Building& b : city.buildings) {
        ASSERT_GE(b.footprint.outer.size(), 3u);
        ASSERT_GT(b.height, b.minHeight);
        ASSERT_LE(b.height, 1000.0f);
    }
    EXPECT_EQ(countOf(city.dropped, "underground"), e.underground);
    EXPECT_EQ(countOf(city.dropped, "part_underground"), e.partsUnderground);
    EXPECT_EQ(summary["buildings"], city.buildings.size());
    EXPECT_TRUE(city.origin.valid);
}

INSTANTIATE_TEST_SUITE_P(RealData, OsmExtract, testing::ValuesIn(kExtracts),
                         [](const testing::TestParamInfo<Extract>& param) { return std::string(param.param.name); });
