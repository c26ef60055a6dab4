// One rule for "drawn at the surface" (atSurface): the roads' fitting, the bridges, the railways and the
// lamps ask it alike. Nothing in a tunnel or underground is drawn; a bridge=yes way is a deck whatever
// its layer, covered or not; any other way covered or at a negative layer is not drawn.
#include "streets/bridge_mesher.h"
#include "streets/lamp_placement.h"
#include "streets/road_elevation.h"
#include "streets/road_fitting.h"

#include <gtest/gtest.h>

#include <map>
#include <string>

using namespace urbis;

namespace {

struct SurfaceCase {
    bool bridge, tunnel, covered, underground;
    int layer;
    bool drawn;
};

constexpr SurfaceCase kCases[] = {
    {false, false, false, false, 0, true},   {false, false, false, false, 1, true},
    {false, false, false, false, -1, false}, {false, true, false, false, 0, false},
    {false, false, true, false, 0, false},   {false, false, false, true, 0, false},
    {true, false, false, false, 1, true},    {true, false, false, false, -1, true},
    {true, false, false, false, -3, true},   {true, false, true, false, 1, true},   // a covered bridge
    {true, true, false, false, 0, false},    {true, false, false, true, -1, false}, // a bridge underground
};

template <class Way>
Way wayOf(const SurfaceCase& c) {
    Way w;
    w.bridge = c.bridge, w.tunnel = c.tunnel, w.covered = c.covered, w.underground = c.underground;
    w.layer = c.layer;
    return w;
}

} // namespace

TEST(StreetsSurfaceRule, RoadsAndRailwaysByTheSameTable) {
    for (const SurfaceCase& c : kCases) {
        EXPECT_EQ(atSurface(wayOf<Road>(c)), c.drawn) << "bridge " << c.bridge << " layer " << c.layer;
        EXPECT_EQ(atSurface(wayOf<Railway>(c)), c.drawn) << "bridge " << c.bridge << " layer " << c.layer;
    }
}

TEST(StreetsSurfaceRule, NegativeLayerBridgeIsFittedLiftedDeckedAndLit) {
    // A 200 m layer=-1 bridge between two ground roads, and a layer=-1 road that is no bridge beside it.
    CityModel city;
    Road west, bridge, east, sunken;
    west.centerline = {{-300, 0}, {-100, 0}};
    bridge.centerline = {{-100, 0}, {0, 0}, {100, 0}};
    east.centerline = {{100, 0}, {300, 0}};
    sunken.centerline = {{-300, 60}, {300, 60}};
    bridge.bridge = true;
    bridge.layer = -1;
    sunken.layer = -1;
    for (Road* r : {&west, &bridge, &east, &sunken}) {
        r->width = 7.0f;
        r->highway = HighwayClass::Secondary;
        city.roads.push_back(*r);
    }
    std::map<std::string, uint64_t> dropped;
    const std::vector<Road> fitted = fitRoads(city, dropped);
    EXPECT_EQ(dropped["road_not_at_surface"], 1u);   // the sunken road only
    size_t bridges = 0, onBridge = 0;
    for (const Road& r : fitted) bridges += r.bridge ? 1 : 0;
    ASSERT_EQ(bridges, 1u);

    const std::vector<std::vector<float>> elevations = roadElevations(fitted);
    for (size_t i = 0; i < fitted.size(); ++i)
        if (fitted[i].bridge) {
            float top = 0;
            for (float e : elevations[i]) top = std::max(top, e);
            EXPECT_FLOAT_EQ(top, bridgeClearance(-1)) << "the deck is lifted to its clearance";
        }
    StreetMesh mesh;
    meshBridges(fitted, elevations, StreetOptions{}, mesh);
    EXPECT_EQ(mesh.counts["bridges"], 1u);
    EXPECT_GT(mesh.trianglesByKind["bridges"], 0u);

    // Lamps stand along it (none are mapped), and none along the sunken road.
    for (const Lamp& lamp : streetLamps(city, fitted)) {
        EXPECT_GT(std::fabs(lamp.position.y - 60.0), 10.0) << "a lamp by the road below the surface";
        onBridge += std::fabs(lamp.position.x) < 90.0 && std::fabs(lamp.position.y) < 10.0 ? 1 : 0;
    }
    EXPECT_GE(onBridge, 2u);
}
