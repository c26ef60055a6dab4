// Heights of untagged buildings: the type table, the order of the estimates, the hidden-tag error.
#include "osm/height_estimate.h"
#include "osm/height_evaluation.h"
#include "osm/height_table.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace urbis;

namespace {

/// A 10 x 10 m building of `type` centred at (x, y); tagged with `height` when it is positive.
Building square(int64_t id, double x, double y, BuildingType type, float height = 0.0f) {
    Building b;
    b.osmId = id;
    b.type = type;
    b.footprint.outer = {{x - 5, y - 5}, {x + 5, y - 5}, {x + 5, y + 5}, {x - 5, y + 5}};
    b.height = height > 0.0f ? height : 3.0f;
    b.heightSource = height > 0.0f ? HeightSource::HeightTag : HeightSource::TypeTable;
    return b;
}

CityModel cityAt(double lat, double lon, std::vector<Building> buildings) {
    CityModel city;
    city.origin = {true, lat, lon};
    city.buildings = std::move(buildings);
    return city;
}

const Building& byId(const CityModel& city, int64_t id) {
    return *std::find_if(city.buildings.begin(), city.buildings.end(), [id](const Building& b) { return b.osmId == id; });
}

constexpr double kLondonLat = 51.51, kLondonLon = -0.09;

} // namespace

TEST(HeightTable, RegionsFromOrigin) {
    const struct {
        double lat, lon;
        Region region;
    } cases[] = {{51.51, -0.09, Region::Europe},       {55.75, 37.62, Region::Europe},
                 {52.48, 13.43, Region::Europe},       {48.14, 10.07, Region::Europe},
                 {37.79, -122.40, Region::NorthAmerica}, {40.72, -73.74, Region::NorthAmerica},
                 {35.68, 139.77, Region::EastAsia},    {-33.87, 151.21, Region::Other},
                 {-23.55, -46.63, Region::Other}};
    for (const auto& c : cases) EXPECT_EQ(regionOf(c.lat, c.lon), c.region) << c.lat << "," << c.lon;
}

TEST(HeightTable, TypicalHeightsByTypeAndRegion) {
    const struct {
        BuildingType type;
        Region region;
        float min, max;
    } cases[] = {
        {BuildingType::House, Region::Europe, 6, 10},         {BuildingType::House, Region::NorthAmerica, 6, 10},
        {BuildingType::Residential, Region::Europe, 13, 19},  {BuildingType::Residential, Region::NorthAmerica, 6, 12},
        {BuildingType::Apartments, Region::EastAsia, 30, 60}, {BuildingType::Retail, Region::Other, 4, 8},
        {BuildingType::Warehouse, Region::Europe, 6, 10},     {BuildingType::Religious, Region::Other, 12, 20},
        {BuildingType::Garage, Region::Europe, 2.7f, 3.3f},   {BuildingType::Shed, Region::NorthAmerica, 2.2f, 2.8f}};
    for (const auto& c : cases) {
        const HeightSpan span = typicalHeight(c.type, c.region);
        EXPECT_FLOAT_EQ(span.min, c.min) << int(c.type) << " " << int(c.region);
        EXPECT_FLOAT_EQ(span.max, c.max) << int(c.type) << " " << int(c.region);
    }
    for (int t = 0; t <= int(BuildingType::Roof); ++t)
        for (Region r : {Region::Other, Region::Europe, Region::NorthAmerica, Region::EastAsia}) {
            const HeightSpan span = typicalHeight(BuildingType(t), r);
            EXPECT_GT(span.min, 0.0f) << t;
            EXPECT_LE(span.min, span.max) << t;
        }
}

TEST(HeightEstimate, TaggedBuildingsKeepTheirTags) {
    CityModel city = cityAt(kLondonLat, kLondonLon, {square(1, 0, 0, BuildingType::House, 42.0f)});
    city.buildings.push_back(square(2, 20, 0, BuildingType::House, 7.0f));
    city.buildings[1].heightSource = HeightSource::Levels;
    estimateHeights(city, {});
    EXPECT_EQ(byId(city, 1).height, 42.0f);
    EXPECT_EQ(byId(city, 1).heightSource, HeightSource::HeightTag);
    EXPECT_EQ(byId(city, 2).height, 7.0f);
    EXPECT_EQ(byId(city, 2).heightSource, HeightSource::Levels);
}

TEST(HeightEstimate, UntaggedHouseGetsTheMedianOfTaggedHousesNearby) {
    CityModel city = cityAt(kLondonLat, kLondonLon,
                            {square(1, 0, 0, BuildingType::House), square(2, 30, 0, BuildingType::House, 6.0f),
                             square(3, 0, 40, BuildingType::House, 9.0f), square(4, -50, 0, BuildingType::House, 7.0f),
                             square(5, 0, -60, BuildingType::House, 8.0f),
                             // A house with only two tagged ones within 150 m looks twice as far.
                             square(8, 200, 200, BuildingType::House, 20.0f), square(9, 220, 200, BuildingType::House, 20.0f),
                             square(10, 250, 150, BuildingType::House),
                             // Taller, but of another type or too far for house 1: not its neighbours.
                             square(6, 10, 10, BuildingType::Office, 60.0f),
                             square(7, 400, 0, BuildingType::House, 30.0f)});
    city.buildings[0].minHeight = 1.0f;
    estimateHeights(city, {});
    EXPECT_EQ(byId(city, 1).heightSource, HeightSource::NearbyMedian);
    EXPECT_FLOAT_EQ(byId(city, 1).height, 1.0f + 7.5f); // above its base: the median of 6, 7, 8, 9
    // Within 300 m of house 10: 2 (6 m), 3 (9 m), 7 (30 m), 8 and 9 (20 m).
    EXPECT_EQ(byId(city, 10).heightSource, HeightSource::NearbyMedian);
    EXPECT_FLOAT_EQ(byId(city, 10).height, 20.0f);
}

TEST(HeightEstimate, IsolatedChurchGetsTheTableValue) {
    // Two tagged churches nearby are too few; the houses are of another type.
    CityModel city = cityAt(kLondonLat, kLondonLon,
                            {square(1, 0, 0, BuildingType::Religious), square(2, 30, 0, BuildingType::Religious, 40.0f),
                             square(3, 0, 30, BuildingType::Religious, 40.0f), square(4, 30, 30, BuildingType::House, 6.0f),
                             square(5, -30, 30, BuildingType::House, 6.0f), square(6, 30, -30, BuildingType::House, 6.0f)});
    estimateHeights(city, {});
    const Building& church = byId(city, 1);
    const HeightSpan span = typicalHeight(BuildingType::Religious, Region::Europe);
    EXPECT_EQ(church.heightSource, HeightSource::TypeTable);
    EXPECT_GE(church.height, span.min);
    EXPECT_LE(church.height, span.max);
}

TEST(HeightEstimate, OverrideRangeWins) {
    CityModel city = cityAt(kLondonLat, kLondonLon,
                            {square(1, 0, 0, BuildingType::House), square(2, 30, 0, BuildingType::House, 6.0f),
                             square(3, 0, 30, BuildingType::House, 6.0f), square(4, 30, 30, BuildingType::House, 6.0f),
                             square(5, 500, 0, BuildingType::Shed)});
    ImportOptions options;
    options.untaggedHeightRange = {{20.0f, 100.0f}};
    estimateHeights(city, options);
    for (int64_t id : {1, 5}) {
        EXPECT_EQ(byId(city, id).heightSource, HeightSource::Range) << id;
        EXPECT_GE(byId(city, id).height, 20.0f) << id;
        EXPECT_LE(byId(city, id).height, 100.0f) << id;
    }
    EXPECT_EQ(byId(city, 2).height, 6.0f);
}

TEST(HeightEstimate, TaggedRoofKeepsAStoreyUnderIt) {
    CityModel city = cityAt(kLondonLat, kLondonLon, {square(1, 0, 0, BuildingType::Shed)});
    city.buildings[0].roofHeight = 6.0f;
    ImportOptions options;
    estimateHeights(city, options);
    EXPECT_FLOAT_EQ(city.buildings[0].height, 6.0f + options.metresPerLevel);
}

TEST(HeightEstimate, SeededPerBuildingAndIndependentOfOrder) {
    std::vector<Building> buildings;
    for (int i = 0; i < 40; ++i)
        buildings.push_back(square(100 + i, 1000.0 * i, 0, BuildingType::Residential, i % 4 == 0 ? 15.0f : 0.0f));
    CityModel a = cityAt(kLondonLat, kLondonLon, buildings);
    std::reverse(buildings.begin(), buildings.end());
    CityModel b = cityAt(kLondonLat, kLondonLon, buildings);
    estimateHeights(a, {});
    estimateHeights(b, {});
    ImportOptions otherSeed;
    otherSeed.seed = 2;
    CityModel c = cityAt(kLondonLat, kLondonLon, buildings);
    estimateHeights(c, otherSeed);
    int differ = 0;
    for (const Building& x : a.buildings) {
        EXPECT_EQ(x.height, byId(b, x.osmId).height) << x.osmId;
        differ += x.height != byId(c, x.osmId).height;
    }
    EXPECT_GT(differ, 20); // the table's variation follows the seed
    EXPECT_NE(byId(a, 101).height, byId(a, 102).height);
}

TEST(HeightEvaluation, HiddenTagsAreEstimatedFromTheRest) {
    // A street of 7 m houses: any hidden one is estimated as 7 m from its tagged neighbours.
    std::vector<Building> houses;
    for (int i = 0; i < 30; ++i) houses.push_back(square(i + 1, 12.0 * i, 0, BuildingType::House, 7.0f));
    const CityModel city = cityAt(kLondonLat, kLondonLon, houses);
    const HeightError exact = evaluateHeightEstimate(city, {});
    EXPECT_GT(exact.hidden, 5u);
    EXPECT_LT(exact.hidden, 25u);
    EXPECT_FLOAT_EQ(float(exact.median), 0.0f);
    EXPECT_FLOAT_EQ(float(exact.p90), 0.0f);
    ImportOptions old;
    old.untaggedHeightRange = {{20.0f, 100.0f}};
    const HeightError range = evaluateHeightEstimate(city, old);
    EXPECT_EQ(range.hidden, exact.hidden);
    EXPECT_GT(range.median, 13.0);
}
