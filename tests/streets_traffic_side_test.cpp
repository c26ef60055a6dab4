// The side traffic keeps, by place (trafficSideAt's table of boxes), and the London extract's streets
// meshed with it: lanes and stop lines mirrored where traffic keeps left.
#include "geometry/road_markings.h"
#include "osm/osm_import.h"
#include "streets/street_mesher.h"
#include "streets/traffic_side.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>
#include <string>

using namespace urbis;

namespace {

struct Place {
    const char* name;
    double lat, lon;
    TrafficSide side;
};

// Cities either side of the boxes' edges as well as inside them.
constexpr Place kPlaces[] = {
    {"London", 51.507, -0.128, TrafficSide::Left},      {"Dublin", 53.350, -6.260, TrafficSide::Left},
    {"Edinburgh", 55.953, -3.189, TrafficSide::Left},   {"Tokyo", 35.680, 139.690, TrafficSide::Left},
    {"Fukuoka", 33.590, 130.402, TrafficSide::Left},    {"Sapporo", 43.062, 141.354, TrafficSide::Left},
    {"Sydney", -33.869, 151.209, TrafficSide::Left},    {"Auckland", -36.848, 174.763, TrafficSide::Left},
    {"Mumbai", 19.076, 72.878, TrafficSide::Left},      {"Delhi", 28.614, 77.209, TrafficSide::Left},
    {"Kolkata", 22.573, 88.364, TrafficSide::Left},     {"Kathmandu", 27.717, 85.324, TrafficSide::Left},
    {"Lahore", 31.549, 74.344, TrafficSide::Left},      {"Hong Kong", 22.285, 114.158, TrafficSide::Left},
    {"Bangkok", 13.756, 100.502, TrafficSide::Left},    {"Singapore", 1.352, 103.820, TrafficSide::Left},
    {"Jakarta", -6.208, 106.846, TrafficSide::Left},    {"Nairobi", -1.292, 36.822, TrafficSide::Left},
    {"Johannesburg", -26.204, 28.047, TrafficSide::Left}, {"Valletta", 35.899, 14.514, TrafficSide::Left},
    {"Kingston", 17.971, -76.793, TrafficSide::Left},
    {"San Francisco", 37.775, -122.419, TrafficSide::Right}, {"New York", 40.713, -74.006, TrafficSide::Right},
    {"Paris", 48.857, 2.352, TrafficSide::Right},       {"Calais", 50.951, 1.858, TrafficSide::Right},
    {"Berlin", 52.520, 13.405, TrafficSide::Right},     {"Busan", 35.180, 129.076, TrafficSide::Right},
    {"Seoul", 37.567, 126.978, TrafficSide::Right},     {"Shenzhen", 22.543, 114.058, TrafficSide::Right},
    {"Lhasa", 29.650, 91.100, TrafficSide::Right},      {"Kabul", 34.529, 69.172, TrafficSide::Right},
    {"Yangon", 16.840, 96.173, TrafficSide::Right},     {"Manila", 14.600, 120.984, TrafficSide::Right},
    {"Kigali", -1.944, 30.062, TrafficSide::Right},     {"Moscow", 55.756, 37.617, TrafficSide::Right},
    {"Havana", 23.113, -82.366, TrafficSide::Right},
};

} // namespace

TEST(StreetsTrafficSide, ByPlace) {
    for (const Place& p : kPlaces) EXPECT_EQ(trafficSideAt(p.lat, p.lon), p.side) << p.name;
    EXPECT_EQ(trafficSideOf(GeoOrigin{}), TrafficSide::Right) << "a city placed nowhere keeps right";
    EXPECT_EQ(trafficSideOf(GeoOrigin{true, 51.5, -0.1}), TrafficSide::Left);
}

TEST(StreetsTrafficSide, LondonKeepsLeft) {
    const std::string path = std::string(URBIS_SHARED_DATA) + "/london_city_2020.osm.pbf";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " not found, skipping";
    const CityModel city = importOsm(path, {});
    ASSERT_EQ(trafficSideOf(city.origin), TrafficSide::Left);
    StreetOptions options;
    const StreetMesh right = meshStreets(city, options);
    options.leftHandTraffic = true;
    const StreetMesh left = meshStreets(city, options);
    ASSERT_EQ(left.roadSegments.size(), right.roadSegments.size());
    size_t stops = 0, mirrored = 0;
    for (size_t i = 0; i < left.roadSegments.size(); ++i) {
        const RoadSegment &l = left.roadSegments[i], &r = right.roadSegments[i];
        // Every line but a zebra's (the same either way) is mirrored.
        const uint32_t lines = r.markings & ~uint32_t(kMarkZebraAtStart | kMarkZebraAtEnd);
        EXPECT_EQ(lines != 0, (l.markings & kMarkLeftHand) != 0) << "segment " << i;
        EXPECT_EQ(l.centreOffset, -r.centreOffset) << "segment " << i;
        // A stop line where traffic arrives at the segment's end: 0.6 m left of the centre line (on the
        // arriving lanes, clear of the centre line and of any divider), none 0.6 m right of it.
        // (On a segment under 5 m the start's stop line may lie there too.)
        if (!(l.markings & kMarkStopAtEnd) || l.lanesBackward == 0 || (l.markings & kMarkZebraAtEnd) || l.length < 5.0f)
            continue;
        ++stops;
        const float along = l.length - marking::kStopLineSetback - 0.5f * marking::kStopLineWidth;
        mirrored += roadPaintAt(l, along, l.centreOffset + 0.6f) != kNoPaint &&
                            roadPaintAt(l, along, l.centreOffset - 0.6f) == kNoPaint
                        ? 1
                        : 0;
    }
    std::cout << stops << " stop lines at segments' ends, " << mirrored << " on the left lanes only\n";
    EXPECT_GT(stops, 50u);
    EXPECT_EQ(mirrored, stops);
}
