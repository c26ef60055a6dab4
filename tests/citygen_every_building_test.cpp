// Every building of every real extract meshes, with its own roof and with each roof shape forced on
// it (untagged buildings are flat, so forcing the shapes is what reaches the straight skeleton on
// every footprint): no crash, no exception, each building meshed or counted as dropped. One test
// per extract, so that ctest runs them side by side.
#include "osm/osm_import.h"
#include "roof_test_buildings.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <numeric>
#include <set>

using namespace urbis;
using namespace urbis::test;

namespace {

struct Extract {
    const char* name;
    std::string path;
    bool required;    ///< always present (Debian's osmnx test data) or else skipped
    size_t stride;    ///< the forced shapes go on every stride-th building (all keep their own roof)
};

const std::string kOsmnx = URBIS_OSMNX_DATA, kShared = URBIS_SHARED_DATA;

const Extract kExtracts[] = {
    {"Village", kOsmnx + "/planet_10.068,48.135_10.071,48.137.osm", true, 1},
    {"WestOakland", kOsmnx + "/West-Oakland.osm.bz2", true, 1},
    // Every shape on every building of the big extracts takes over a minute on two cores: they
    // take a fixed sample (every stride-th building, the same on every run) for the forced shapes,
    // which keeps each test under about 10 s of one core.
    {"SanFrancisco", kShared + "/sf_downtown_2023.osm.pbf", false, 5},
    {"London", kShared + "/london_city_2020.osm.pbf", false, 2},
    {"Moscow", kShared + "/moscow_center_2020.osm.pbf", false, 1},
    {"Berlin", kShared + "/berlin_neukolln_2024.osm", false, 1},
    {"NewYork", kShared + "/nyc_queens_village_2016.osm.pbf", false, 20},
    {"SkeletonCrash", kShared + "/regressions/skeleton_crash_building.osm", false, 1},
};

void PrintTo(const Extract& e, std::ostream* os) { *os << e.name; }

/// Buildings with at least one triangle or wall record in `out`.
size_t meshedBuildings(const CityMesh& out) {
    std::set<uint32_t> objects;
    for (const TriangleInfo& info : out.mesh.info) objects.insert(info.object);
    for (const WallRecord& w : out.walls) objects.insert(w.object);
    objects.erase(0);  // the ground
    return objects.size();
}

/// Meshes `city` and checks that each building was meshed or counted; returns the failures.
uint64_t meshAndAccount(const CityModel& city, const std::string& what) {
    CityMesh out;
    CityMeshOptions buildingsOnly;   // the streets' objects and drops are theirs to count (tests/streets_*)
    buildingsOnly.streets = false;
    EXPECT_NO_THROW(out = meshCity(city, buildingsOnly)) << what;
    const uint64_t dropped = std::accumulate(out.dropped.begin(), out.dropped.end(), uint64_t(0),
                                             [](uint64_t n, const auto& reason) { return n + reason.second; });
    EXPECT_EQ(meshedBuildings(out) + dropped, city.buildings.size()) << what;
    for (const auto& [reason, n] : out.dropped) std::cout << what << ": dropped " << reason << " x" << n << "\n";
    for (const auto& [reason, n] : out.roofFallbacks) std::cout << what << ": fallback " << reason << " x" << n << "\n";
    const auto failed = out.dropped.find("mesh_failed");
    return failed == out.dropped.end() ? 0 : failed->second;
}

class EveryBuilding : public testing::TestWithParam<Extract> {};

} // namespace

TEST_P(EveryBuilding, MeshesWithEveryRoofShape) {
    const Extract& e = GetParam();
    if (!std::filesystem::exists(e.path)) {
        ASSERT_FALSE(e.required) << e.path << " is missing";
        GTEST_SKIP() << e.path << " not found (the shared data), skipping";
    }
    const CityModel city = importOsm(e.path, {});
    uint64_t failed = meshAndAccount(city, std::string(e.name) + " as tagged");
    CityModel sample = city;
    sample.buildings.clear();
    for (size_t i = 0; i < city.buildings.size(); i += e.stride) sample.buildings.push_back(city.buildings[i]);
    for (RoofShape shape : kAllShapes) {
        for (Building& b : sample.buildings) b.roofShape = shape;
        failed += meshAndAccount(sample, std::string(e.name) + " shape " + std::to_string(int(shape)));
    }
    // A throw is caught and counted, but none is expected from real data.
    EXPECT_EQ(failed, 0u);
}

INSTANTIATE_TEST_SUITE_P(Extracts, EveryBuilding, testing::ValuesIn(kExtracts),
                         [](const testing::TestParamInfo<Extract>& p) { return std::string(p.param.name); });
