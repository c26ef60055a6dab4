// Generated city: parameter checks, determinism and building counts.
#include "layout/city_layout.h"
#include "base/input_error.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <chrono>
#include <cstring>
#include <limits>

using namespace urbis;

namespace {

bool sameRing(const Ring& a, const Ring& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec2d)) == 0;
}

bool samePolygon(const Polygon& a, const Polygon& b) {
    if (!sameRing(a.outer, b.outer) || a.holes.size() != b.holes.size()) return false;
    for (size_t i = 0; i < a.holes.size(); ++i)
        if (!sameRing(a.holes[i], b.holes[i])) return false;
    return true;
}

bool sameBuilding(const Building& a, const Building& b) {
    auto rgb = [](Rgb x, Rgb y) { return x.r == y.r && x.g == y.g && x.b == y.b; };
    return samePolygon(a.footprint, b.footprint) && a.height == b.height && a.roofHeight == b.roofHeight &&
           a.minHeight == b.minHeight && a.levels == b.levels && a.heightSource == b.heightSource &&
           a.roofShape == b.roofShape && a.roofDirection == b.roofDirection && a.type == b.type &&
           a.material == b.material && rgb(a.wallColour, b.wallColour) && rgb(a.roofColour, b.roofColour) &&
           a.seed == b.seed;
}

// Field-by-field equality of everything a generated city fills in.
void expectSameCity(const CityModel& a, const CityModel& b) {
    ASSERT_EQ(a.buildings.size(), b.buildings.size());
    for (size_t i = 0; i < a.buildings.size(); ++i)
        ASSERT_TRUE(sameBuilding(a.buildings[i], b.buildings[i])) << "building " << i;
    ASSERT_EQ(a.roads.size(), b.roads.size());
    for (size_t i = 0; i < a.roads.size(); ++i) {
        const Road &x = a.roads[i], &y = b.roads[i];
        ASSERT_TRUE(sameRing(x.centerline, y.centerline) && x.highway == y.highway && x.width == y.width &&
                    x.lanes == y.lanes && x.lanesForward == y.lanesForward && x.lanesBackward == y.lanesBackward &&
                    x.oneway == y.oneway && x.sidewalk == y.sidewalk && x.sidewalkLeftWidth == y.sidewalkLeftWidth &&
                    x.sidewalkRightWidth == y.sidewalkRightWidth && x.surface == y.surface &&
                    x.bridge == y.bridge && x.layer == y.layer && x.overtaking == y.overtaking)
            << "road " << i;
    }
    ASSERT_EQ(a.crossings.size(), b.crossings.size());
    for (size_t i = 0; i < a.crossings.size(); ++i)
        ASSERT_TRUE(a.crossings[i].position.x == b.crossings[i].position.x &&
                    a.crossings[i].position.y == b.crossings[i].position.y && a.crossings[i].kind == b.crossings[i].kind);
    ASSERT_EQ(a.lamps.size(), b.lamps.size());
    ASSERT_EQ(a.trees.size(), b.trees.size());
    for (size_t i = 0; i < a.trees.size(); ++i)
        ASSERT_TRUE(a.trees[i].position.x == b.trees[i].position.x && a.trees[i].position.y == b.trees[i].position.y &&
                    a.trees[i].height == b.trees[i].height && a.trees[i].crownDiameter == b.trees[i].crownDiameter);
    ASSERT_EQ(a.areas.size(), b.areas.size());
    for (size_t i = 0; i < a.areas.size(); ++i)
        ASSERT_TRUE(samePolygon(a.areas[i].polygon, b.areas[i].polygon) && a.areas[i].kind == b.areas[i].kind &&
                    a.areas[i].surface == b.areas[i].surface);
}

LayoutParams withCount(uint64_t n) {
    LayoutParams p;
    p.buildings = n;
    return p;
}

} // namespace

TEST(LayoutParams, ImpossibleParametersThrowInputError) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    auto params = [](uint64_t n, float lo, float hi) {
        LayoutParams p;
        p.buildings = n;
        p.minBuildingHeight = lo;
        p.maxBuildingHeight = hi;
        return p;
    };
    EXPECT_THROW(generateCity(params(0, 8, 120)), InputError);
    EXPECT_THROW(generateCity(params(kMaxGeneratedBuildings + 1, 8, 120)), InputError);
    EXPECT_THROW(generateCity(params(10, 50, 20)), InputError);
    EXPECT_THROW(generateCity(params(10, -5, 20)), InputError);
    EXPECT_THROW(generateCity(params(10, 0, 20)), InputError);
    EXPECT_THROW(generateCity(params(10, 8, nan)), InputError);
    EXPECT_THROW(generateCity(params(10, 8, std::numeric_limits<float>::infinity())), InputError);
    EXPECT_NO_THROW(generateCity(params(1, 10, 10)));
}

TEST(LayoutParams, SameSeedGivesIdenticalCity) {
    LayoutParams p = withCount(3000);
    p.seed = 7;
    CityModel a = generateCity(p);
    CityModel b;
    {
        tbb::global_control serial(tbb::global_control::max_allowed_parallelism, 1);
        b = generateCity(p);  // the result must not depend on how the work was split
    }
    expectSameCity(a, b);
    EXPECT_EQ(a.source, "generated");
    EXPECT_FALSE(a.origin.valid);
}

TEST(LayoutParams, DifferentSeedGivesDifferentCity) {
    LayoutParams p = withCount(3000);
    CityModel a = generateCity(p);
    p.seed = 2;
    CityModel b = generateCity(p);
    ASSERT_EQ(a.buildings.size(), b.buildings.size());
    size_t differing = 0;
    for (size_t i = 0; i < a.buildings.size(); ++i)
        differing += samePolygon(a.buildings[i].footprint, b.buildings[i].footprint) ? 0 : 1;
    EXPECT_GT(differing, a.buildings.size() * 9 / 10);
    EXPECT_NE(a.roads[0].centerline[0].y, b.roads[0].centerline[0].y);
}

// The layout promises exactly the target count, well inside the +-5% that callers may rely on.
class LayoutCount : public ::testing::TestWithParam<uint64_t> {};

TEST_P(LayoutCount, ExactlyTheTargetNumberOfBuildings) {
    const uint64_t target = GetParam();
    auto t0 = std::chrono::steady_clock::now();
    CityModel city = generateCity(withCount(target));
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("generateCity(%llu buildings): %.3f s, %zu roads, %zu crossings, %zu trees, %zu areas\n",
                static_cast<unsigned long long>(target), seconds, city.roads.size(), city.crossings.size(),
                city.trees.size(), city.areas.size());
    EXPECT_EQ(city.buildings.size(), target);
    EXPECT_NEAR(static_cast<double>(city.buildings.size()), static_cast<double>(target), 0.05 * static_cast<double>(target));
}

INSTANTIATE_TEST_SUITE_P(Sizes, LayoutCount, ::testing::Values(1u, 100u, 10'000u, 1'000'000u));
