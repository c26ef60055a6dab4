// The sports centre whose footprint crashed CGAL's straight skeleton (shared/data/regressions): GEOS
// repairs its self-touching ring into an outer ring and a sliver hole that touches it at one point.
#include "cli_support.h"
#include "mesh_checks.h"
#include "osm/osm_import.h"
#include "roof_test_buildings.h"

#include <gtest/gtest.h>

#include <filesystem>

using namespace urbis;
using namespace urbis::test;
namespace fs = std::filesystem;

namespace {

const std::string kCrashBuilding = URBIS_SHARED_DATA "/regressions/skeleton_crash_building.osm";

} // namespace

TEST(SkeletonRegression, CrashBuildingGetsAClosedRoofOfEveryShape) {
    if (!fs::exists(kCrashBuilding)) GTEST_SKIP() << kCrashBuilding << " not found (the shared data), skipping";
    const CityModel city = importOsm(kCrashBuilding, {});
    ASSERT_EQ(city.buildings.size(), 1u);
    ASSERT_EQ(city.buildings[0].footprint.holes.size(), 1u) << "the repaired footprint no longer has its touching hole";
    for (RoofShape shape : kAllShapes) {
        Building b = city.buildings[0];
        b.roofShape = shape;
        b.minHeight = 0.5f;  // a floor, so that the building is a closed mesh
        const CityMesh out = meshOne(b);
        EXPECT_TRUE(out.dropped.empty()) << "shape " << int(shape) << ": " << out.dropped.begin()->first;
        EXPECT_GT(out.trianglesByKind.at("roofs"), 0u) << "shape " << int(shape);
        EXPECT_EQ(out.holesDropped, 1u);
        EXPECT_EQ(out.roofFallbacks.count("skeleton_failed"), 0u) << "shape " << int(shape);
        EXPECT_EQ(openEdges(out.mesh), 0u) << "shape " << int(shape) << ": walls and roof must share the cleaned ring";
    }
}

TEST(SkeletonRegression, CrashBuildingRenders) {
    if (!fs::exists(kCrashBuilding)) GTEST_SKIP() << kCrashBuilding << " not found (the shared data), skipping";
    const fs::path dir = scratchDir("skeleton_crash");
    const CommandResult r = runUrbis("render --osm '" + kCrashBuilding + "' --width 64 --height 64 --spp 1", dir);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir / "urbis.png"));
}
