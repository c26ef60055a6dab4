// Which lines a road carries (streets/marking_rules.h), table-driven: one road per row, changed from
// a plain two-lane residential street 7 m wide, and the RoadMarking bits it must get.
#include "scene/road_segment.h"
#include "streets/marking_rules.h"

#include <gtest/gtest.h>

#include <functional>

using namespace urbis;

namespace {

struct RuleCase {
    const char* name;
    std::function<void(Road&)> change;
    bool american;
    uint32_t bits;
};

constexpr uint32_t kDashedCentre = kMarkCentreLine | kMarkCentreDashed;

} // namespace

TEST(MarkingRules, ByClassLanesSurfaceAndTags) {
    const RuleCase cases[] = {
        {"residential two lanes", [](Road&) {}, false, kDashedCentre},
        {"service road", [](Road& r) { r.highway = HighwayClass::Service; }, false, 0},
        {"living street", [](Road& r) { r.highway = HighwayClass::LivingStreet; }, false, 0},
        {"footway", [](Road& r) { r.highway = HighwayClass::Footway; }, false, 0},
        {"track", [](Road& r) { r.highway = HighwayClass::Track; }, false, 0},
        {"lane_markings=no", [](Road& r) { r.laneMarkings = false; }, false, 0},
        {"gravel", [](Road& r) { r.surface = RoadSurface::Gravel; }, false, 0},
        {"dirt", [](Road& r) { r.surface = RoadSurface::Dirt; }, false, 0},
        {"sett", [](Road& r) { r.surface = RoadSurface::Sett; }, false, 0},
        {"cobblestone", [](Road& r) { r.surface = RoadSurface::Cobblestone; }, false, 0},
        {"concrete", [](Road& r) { r.surface = RoadSurface::Concrete; }, false, kDashedCentre},
        {"overtaking=no", [](Road& r) { r.overtaking = false; }, false, kMarkCentreLine},
        {"one lane", [](Road& r) { r.lanes = 1; }, false, 0},
        {"narrower than a centre line needs", [](Road& r) { r.width = 5.0f; }, false, 0},
        {"primary four lanes",
         [](Road& r) {
             r.highway = HighwayClass::Primary;
             r.lanes = 4;
             r.width = 13.0f;
         },
         false, kMarkCentreLine | kMarkLaneDividers},
        {"primary two lanes", [](Road& r) { r.highway = HighwayClass::Primary; }, false, kDashedCentre},
        {"lanes:forward=2 lanes:backward=1",
         [](Road& r) {
             r.highway = HighwayClass::Secondary;
             r.lanes = 3;
             r.lanesForward = 2;
             r.lanesBackward = 1;
             r.width = 10.0f;
         },
         false, kMarkCentreLine | kMarkLaneDividers},
        {"one-way two lanes",
         [](Road& r) {
             r.oneway = true;
             r.highway = HighwayClass::Tertiary;
         },
         false, kMarkLaneDividers},
        {"one-way one lane",
         [](Road& r) {
             r.oneway = true;
             r.lanes = 1;
         },
         false, 0},
        {"motorway carriageway",
         [](Road& r) {
             r.highway = HighwayClass::Motorway;
             r.oneway = true;
             r.lanes = 3;
             r.width = 11.0f;
         },
         false, kMarkLaneDividers | kMarkEdgeLines},
        {"two-way trunk", [](Road& r) { r.highway = HighwayClass::Trunk; }, false, kMarkCentreLine | kMarkEdgeLines},
        {"american two lanes", [](Road&) {}, true, kDashedCentre | kMarkCentreYellow | kMarkAmerican},
        {"american no passing", [](Road& r) { r.overtaking = false; }, true,
         kMarkCentreLine | kMarkCentreYellow | kMarkAmerican},
        {"american one-way", [](Road& r) { r.oneway = true; }, true, kMarkLaneDividers | kMarkAmerican},
        {"american service road", [](Road& r) { r.highway = HighwayClass::Service; }, true, 0},
    };
    for (const RuleCase& c : cases) {
        Road road;
        road.width = 7.0f;
        c.change(road);
        EXPECT_EQ(markingBits(road, c.american), c.bits) << c.name;
    }
}

TEST(MarkingRules, PavedSurfaces) {
    EXPECT_TRUE(isPaved(RoadSurface::Asphalt));
    EXPECT_TRUE(isPaved(RoadSurface::Sett));
    EXPECT_TRUE(isPaved(RoadSurface::Unknown));
    EXPECT_FALSE(isPaved(RoadSurface::Gravel));
    EXPECT_FALSE(isPaved(RoadSurface::Dirt));
    EXPECT_FALSE(isPaved(RoadSurface::Grass));
}
