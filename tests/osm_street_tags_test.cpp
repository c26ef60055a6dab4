// Table-driven street tags: roads (width, lanes, sidewalks, surface, flags, levels), crossings,
// railways, ground-cover areas and street lamps, each from a map of tags.
#include "osm/lamp_tags.h"
#include "osm/nature_tags.h"
#include "osm/railway_tags.h"
#include "osm/street_tags.h"
#include "osm/tag_parsing.h"

#include "tag_map.h"

#include <gtest/gtest.h>

#include <map>
#include <optional>
#include <string>
#include <vector>

using namespace urbis;

using test::tagsOf;

namespace {

using Tags = std::map<std::string, std::string>;

/// A road of `tags`, with the issues it raised and whether its line is to be flipped.
struct Parsed {
    Road road;
    std::map<std::string, uint64_t> issues;
    bool reversed = false;
};

Parsed parse(const Tags& tags) {
    Parsed p;
    p.road = roadFromTags(tagsOf(tags), 1, p.reversed, p.issues);
    return p;
}

std::string describe(const Tags& tags) {
    std::string s;
    for (const auto& [k, v] : tags) s += k + "=" + v + " ";
    return s;
}

} // namespace

TEST(StreetTagsRoad, WidthAndLanes) {
    struct Case {
        Tags tags;
        float width;
        int lanes, forward, backward;
    };
    const std::vector<Case> cases = {
        {{{"highway", "residential"}}, 6.0f, 2, 0, 0},                             // class defaults
        {{{"highway", "residential"}, {"oneway", "yes"}}, 6.0f, 1, 0, 0},
        {{{"highway", "primary"}, {"width", "30 ft"}, {"lanes", "4"}}, 9.144f, 4, 0, 0}, // width wins
        {{{"highway", "motorway"}, {"lanes", "3"}}, 3 * 3.5f, 3, 0, 0},
        {{{"highway", "trunk"}, {"lanes", "2"}}, 2 * 3.5f, 2, 0, 0},
        {{{"highway", "primary"}, {"lanes", "2"}}, 2 * 3.25f, 2, 0, 0},
        {{{"highway", "secondary_link"}, {"lanes", "1"}}, 3.25f, 1, 0, 0},
        {{{"highway", "tertiary"}, {"lanes", "2"}}, 2 * 3.0f, 2, 0, 0},
        {{{"highway", "secondary"}, {"lanes:forward", "2"}, {"lanes:backward", "1"}}, 3 * 3.25f, 3, 2, 1},
        {{{"highway", "tertiary"}, {"lanes:forward", "2"}}, 3 * 3.0f, 3, 2, 0},     // the other side: 1
        {{{"highway", "residential"}, {"oneway", "yes"}, {"lanes:forward", "2"}}, 2 * 3.0f, 2, 2, 0},
        {{{"highway", "primary"}, {"lanes", "5"}, {"lanes:forward", "3"}, {"lanes:backward", "2"}}, 5 * 3.25f, 5, 3, 2},
        // oneway=-1 flips the line, so forward and backward swap.
        {{{"highway", "residential"}, {"oneway", "-1"}, {"lanes:forward", "2"}, {"lanes:backward", "1"}}, 9.0f, 3, 1, 2},
        {{{"highway", "residential"}, {"width", "7.5 m"}}, 7.5f, 2, 0, 0},
        {{{"highway", "service"}}, 4.0f, 1, 0, 0},
        {{{"highway", "footway"}}, 2.0f, 1, 0, 0},
    };
    for (const Case& c : cases) {
        const Parsed p = parse(c.tags);
        EXPECT_NEAR(p.road.width, c.width, 1e-4f) << describe(c.tags);
        EXPECT_EQ(p.road.lanes, c.lanes) << describe(c.tags);
        EXPECT_EQ(p.road.lanesForward, c.forward) << describe(c.tags);
        EXPECT_EQ(p.road.lanesBackward, c.backward) << describe(c.tags);
        EXPECT_TRUE(p.issues.empty()) << describe(c.tags);
    }
}

TEST(StreetTagsRoad, BadWidthAndLanesAreCountedAndIgnored) {
    const std::pair<Tags, const char*> cases[] = {
        {{{"highway", "residential"}, {"width", "wide"}}, "road_bad_width_tag"},
        {{{"highway", "residential"}, {"width", "-3"}}, "road_bad_width_tag"},
        {{{"highway", "residential"}, {"width", "150"}}, "road_bad_width_tag"},
        {{{"highway", "residential"}, {"lanes", "0"}}, "road_bad_lanes_tag"},
        {{{"highway", "residential"}, {"lanes", "2;3"}}, "road_bad_lanes_tag"},
        {{{"highway", "residential"}, {"lanes:forward", "99"}}, "road_bad_lanes_tag"},
        {{{"highway", "residential"}, {"sidewalk:left:width", "huge"}}, "road_bad_sidewalk_width_tag"},
        {{{"highway", "residential"}, {"sidewalk:width", "50"}}, "road_bad_sidewalk_width_tag"},
    };
    for (const auto& [tags, issue] : cases) {
        const Parsed p = parse(tags);
        EXPECT_EQ(p.issues.size(), 1u) << describe(tags);
        EXPECT_EQ(p.issues.count(issue), 1u) << describe(tags);
        EXPECT_FLOAT_EQ(p.road.width, 6.0f) << describe(tags);
        EXPECT_EQ(p.road.lanes, 2) << describe(tags);
        EXPECT_EQ(p.road.sidewalkLeftWidth, 0.0f) << describe(tags);
    }
}

TEST(StreetTagsRoad, Sidewalks) {
    struct Case {
        Tags tags;
        Sidewalk sidewalk;
        float left, right;
    };
    const std::vector<Case> cases = {
        {{}, Sidewalk::Unknown, 0, 0},
        {{{"sidewalk", "both"}}, Sidewalk::Both, 0, 0},
        {{{"sidewalk", "yes"}}, Sidewalk::Both, 0, 0},
        {{{"sidewalk", "left"}}, Sidewalk::Left, 0, 0},
        {{{"sidewalk", "right"}}, Sidewalk::Right, 0, 0},
        {{{"sidewalk", "no"}}, Sidewalk::None, 0, 0},
        {{{"sidewalk", "none"}}, Sidewalk::None, 0, 0},
        {{{"sidewalk", "separate"}}, Sidewalk::Separate, 0, 0},
        {{{"sidewalk", "sometimes"}}, Sidewalk::Unknown, 0, 0},
        {{{"sidewalk:both", "yes"}}, Sidewalk::Both, 0, 0},
        {{{"sidewalk:both", "no"}}, Sidewalk::None, 0, 0},
        {{{"sidewalk:both", "separate"}}, Sidewalk::Separate, 0, 0},
        {{{"sidewalk:left", "yes"}}, Sidewalk::Left, 0, 0},
        {{{"sidewalk:right", "yes"}, {"sidewalk:left", "no"}}, Sidewalk::Right, 0, 0},
        {{{"sidewalk:left", "separate"}, {"sidewalk:right", "yes"}}, Sidewalk::Right, 0, 0}, // the drawn one
        {{{"sidewalk:left", "separate"}, {"sidewalk:right", "no"}}, Sidewalk::Separate, 0, 0},
        {{{"sidewalk", "both"}, {"sidewalk:right", "no"}}, Sidewalk::Left, 0, 0},         // a side overrides
        {{{"sidewalk", "no"}, {"sidewalk:both", "yes"}}, Sidewalk::Both, 0, 0},
        {{{"sidewalk", "both"}, {"sidewalk:both:width", "2"}}, Sidewalk::Both, 2, 2},
        {{{"sidewalk", "both"}, {"sidewalk:width", "1.5"}}, Sidewalk::Both, 1.5f, 1.5f},
        {{{"sidewalk", "both"}, {"sidewalk:width", "1.5"}, {"sidewalk:both:width", "2"}}, Sidewalk::Both, 2, 2},
        {{{"sidewalk", "both"}, {"sidewalk:both:width", "2"}, {"sidewalk:left:width", "3 m"}}, Sidewalk::Both, 3, 2},
        {{{"sidewalk", "right"}, {"sidewalk:right:width", "2.5"}}, Sidewalk::Right, 0, 2.5f},
        // A flipped line (oneway=-1) swaps the sides.
        {{{"oneway", "-1"}, {"sidewalk", "left"}, {"sidewalk:left:width", "2"}}, Sidewalk::Right, 0, 2},
    };
    for (const Case& c : cases) {
        Tags tags = c.tags;
        tags["highway"] = "residential";
        const Parsed p = parse(tags);
        EXPECT_EQ(p.road.sidewalk, c.sidewalk) << describe(tags);
        EXPECT_FLOAT_EQ(p.road.sidewalkLeftWidth, c.left) << describe(tags);
        EXPECT_FLOAT_EQ(p.road.sidewalkRightWidth, c.right) << describe(tags);
    }
}

TEST(StreetTagsRoad, Surfaces) {
    using R = RoadSurface;
    const std::pair<const char*, RoadSurface> cases[] = {
        {"asphalt", R::Asphalt},          {"concrete", R::Concrete},        {"concrete:plates", R::Concrete},
        {"concrete:lanes", R::Concrete},  {"paving_stones", R::PavingStones}, {"sett", R::Sett},
        {"unhewn_cobblestone", R::Cobblestone}, {"cobblestone", R::Cobblestone}, {"gravel", R::Gravel},
        {"fine_gravel", R::Gravel},       {"compacted", R::Gravel},         {"pebblestone", R::Gravel},
        {"dirt", R::Dirt},                {"ground", R::Dirt},              {"earth", R::Dirt},
        {"mud", R::Dirt},                 {"sand", R::Dirt},                {"grass", R::Grass},
        {"grass_paver", R::Grass},        {"wood", R::Wood},                {"metal", R::Metal},
        {" asphalt ", R::Asphalt},        {"sett;asphalt", R::Sett},        {"tartan", R::Unknown},
        {"Asphalt", R::Unknown},          {"", R::Unknown}};
    for (const auto& [value, surface] : cases) EXPECT_EQ(parseRoadSurface(value), surface) << value;

    // Only malformed values are counted; an unlisted word is a value we do not draw yet.
    const std::pair<const char*, bool> counted[] = {
        {"asphalt", false}, {"tartan", false}, {"paving_stones:30", false}, {"Asphalt", true},
        {"", true}, {"asph alt", true}, {"asphalt!", true}};
    for (const auto& [value, bad] : counted) {
        const Parsed p = parse({{"highway", "residential"}, {"surface", value}});
        EXPECT_EQ(p.issues.count("road_bad_surface_tag"), bad ? 1u : 0u) << value;
    }
}

TEST(StreetTagsRoad, FlagsAndLevels) {
    struct Case {
        Tags tags;
        int layer;
        bool bridge, tunnel, covered, underground;
        bool badLayer;
    };
    const std::vector<Case> cases = {
        {{}, 0, false, false, false, false, false},
        {{{"bridge", "yes"}, {"layer", "1"}}, 1, true, false, false, false, false},
        {{{"bridge", "viaduct"}}, 0, true, false, false, false, false},
        {{{"bridge", "no"}}, 0, false, false, false, false, false},
        {{{"tunnel", "yes"}, {"layer", "-1"}}, -1, false, true, false, false, false},
        {{{"tunnel", "building_passage"}}, 0, false, true, false, false, false},
        {{{"tunnel", "no"}}, 0, false, false, false, false, false},
        {{{"covered", "yes"}}, 0, false, false, true, false, false},
        {{{"covered", "no"}}, 0, false, false, false, false, false},
        {{{"location", "underground"}}, 0, false, false, false, true, false},
        {{{"location", "underground;indoor"}}, 0, false, false, false, true, false},
        {{{"location", "overground"}}, 0, false, false, false, false, false},
        {{{"layer", "7"}}, 5, false, false, false, false, true},   // clamped
        {{{"layer", "-9"}}, -5, false, false, false, false, true},
        {{{"layer", "x"}}, 0, false, false, false, false, true},
        {{{"layer", "1.5"}}, 0, false, false, false, false, true},
    };
    for (const Case& c : cases) {
        Tags tags = c.tags;
        tags["highway"] = "secondary";
        const Parsed p = parse(tags);
        EXPECT_EQ(p.road.layer, c.layer) << describe(tags);
        EXPECT_EQ(p.road.bridge, c.bridge) << describe(tags);
        EXPECT_EQ(p.road.tunnel, c.tunnel) << describe(tags);
        EXPECT_EQ(p.road.covered, c.covered) << describe(tags);
        EXPECT_EQ(p.road.underground, c.underground) << describe(tags);
        EXPECT_EQ(p.issues.count("road_bad_layer_tag"), c.badLayer ? 1u : 0u) << describe(tags);
    }
}

TEST(StreetTagsRoad, MarkingsOvertakingFootwayAndArea) {
    struct Case {
        Tags tags;
        bool laneMarkings, overtaking, area;
        FootwayKind footway;
    };
    const std::vector<Case> cases = {
        {{}, true, true, false, FootwayKind::None},
        {{{"lane_markings", "no"}}, false, true, false, FootwayKind::None},
        {{{"lane_markings", "yes"}}, true, true, false, FootwayKind::None},
        {{{"overtaking", "no"}}, true, false, false, FootwayKind::None},
        {{{"overtaking:forward", "no"}}, true, true, false, FootwayKind::None},   // one direction may still pass
        {{{"overtaking:forward", "no"}, {"overtaking:backward", "no"}}, true, false, false, FootwayKind::None},
        {{{"footway", "sidewalk"}}, true, true, false, FootwayKind::Sidewalk},
        {{{"footway", "crossing"}}, true, true, false, FootwayKind::Crossing},
        {{{"footway", "access_aisle"}}, true, true, false, FootwayKind::None},
        {{{"area", "yes"}}, true, true, true, FootwayKind::None},
        {{{"area", "no"}}, true, true, false, FootwayKind::None},
    };
    for (const Case& c : cases) {
        Tags tags = c.tags;
        tags["highway"] = "tertiary";
        const Parsed p = parse(tags);
        EXPECT_EQ(p.road.laneMarkings, c.laneMarkings) << describe(tags);
        EXPECT_EQ(p.road.overtaking, c.overtaking) << describe(tags);
        EXPECT_EQ(p.road.area, c.area) << describe(tags);
        EXPECT_EQ(p.road.footway, c.footway) << describe(tags);
    }
}

TEST(StreetTagsCrossing, KindFromCrossingAndMarkings) {
    using K = CrossingKind;
    const std::pair<Tags, std::optional<CrossingKind>> cases[] = {
        {{}, K::Marked},
        {{{"crossing", "zebra"}}, K::Zebra},
        {{{"crossing", "marked"}}, K::Marked},
        {{{"crossing", "uncontrolled"}}, K::Marked},
        {{{"crossing", "traffic_signals"}}, K::TrafficSignals},
        {{{"crossing", "unmarked"}}, K::Unmarked},
        {{{"crossing", "no"}}, std::nullopt},
        {{{"crossing", "uncontrolled"}, {"crossing_ref", "zebra"}}, K::Zebra},
        {{{"crossing", "traffic_signals"}, {"crossing:markings", "zebra"}}, K::Zebra},  // zebra wins
        {{{"crossing", "traffic_signals"}, {"crossing:markings", "no"}}, K::Unmarked},
        {{{"crossing:markings", "yes"}}, K::Marked},
        {{{"crossing:markings", "no"}}, K::Unmarked},
        {{{"crossing", "unmarked"}, {"crossing_ref", "zebra"}}, K::Zebra},
    };
    for (const auto& [tags, kind] : cases) EXPECT_EQ(crossingKindFromTags(tagsOf(tags)), kind) << describe(tags);
    EXPECT_TRUE(isCarriageway(HighwayClass::Residential));
    EXPECT_TRUE(isCarriageway(HighwayClass::Service));
    EXPECT_FALSE(isCarriageway(HighwayClass::Footway));
    EXPECT_FALSE(isCarriageway(HighwayClass::Cycleway));
}

TEST(StreetTagsRailway, KindsGaugeEmbeddingAndLevels) {
    const std::pair<const char*, std::optional<RailKind>> kinds[] = {
        {"rail", RailKind::Rail},     {"light_rail", RailKind::LightRail}, {"tram", RailKind::Tram},
        {"subway", RailKind::Subway}, {"narrow_gauge", RailKind::Narrow},  {"abandoned", std::nullopt},
        {"disused", std::nullopt},    {"razed", std::nullopt},             {"platform", std::nullopt},
        {"level_crossing", std::nullopt}};
    for (const auto& [value, kind] : kinds) EXPECT_EQ(railKindOf(value), kind) << value;
    EXPECT_FALSE(railKindOf(nullptr).has_value());

    struct Case {
        RailKind kind;
        Tags tags;
        float gauge;
        bool embedded;
        const char* issue;
    };
    const std::vector<Case> cases = {
        {RailKind::Rail, {}, 1.435f, false, nullptr},
        {RailKind::Narrow, {}, 1.0f, false, nullptr},
        {RailKind::Narrow, {{"gauge", "1067"}}, 1.067f, false, nullptr},
        {RailKind::Rail, {{"gauge", "1668;1435"}}, 1.668f, false, nullptr},
        {RailKind::Rail, {{"gauge", "standard"}}, 1.435f, false, "railway_bad_gauge_tag"},
        {RailKind::Rail, {{"gauge", "20"}}, 1.435f, false, "railway_bad_gauge_tag"},
        {RailKind::Tram, {}, 1.435f, true, nullptr},
        {RailKind::Tram, {{"embedded", "no"}}, 1.435f, false, nullptr},
        {RailKind::LightRail, {{"embedded", "yes"}}, 1.435f, true, nullptr},
        {RailKind::Rail, {{"embedded", "partial"}}, 1.435f, true, nullptr},
        {RailKind::Subway, {{"layer", "12"}}, 1.435f, false, "railway_bad_layer_tag"},
    };
    for (const Case& c : cases) {
        std::map<std::string, uint64_t> issues;
        const Railway r = railwayFromTags(tagsOf(c.tags), c.kind, 7, issues);
        EXPECT_EQ(r.kind, c.kind) << describe(c.tags);
        EXPECT_NEAR(r.gauge, c.gauge, 1e-6f) << describe(c.tags);
        EXPECT_EQ(r.embedded, c.embedded) << describe(c.tags);
        EXPECT_EQ(issues.size(), c.issue ? 1u : 0u) << describe(c.tags);
        if (c.issue) {
            EXPECT_EQ(issues.count(c.issue), 1u) << describe(c.tags);
        }
    }
    std::map<std::string, uint64_t> issues;
    const Tags levels{{"bridge", "yes"}, {"layer", "2"}, {"tunnel", "no"}, {"covered", "yes"},
                      {"location", "underground"}};
    const Railway r = railwayFromTags(tagsOf(levels), RailKind::Rail, 8, issues);
    EXPECT_EQ(r.osmId, 8);
    EXPECT_EQ(r.layer, 2);
    EXPECT_TRUE(r.bridge);
    EXPECT_FALSE(r.tunnel);
    EXPECT_TRUE(r.covered);
    EXPECT_TRUE(r.underground);
}

TEST(StreetTagsArea, KindsAndPriority) {
    using A = AreaKind;
    const std::pair<Tags, std::optional<AreaKind>> cases[] = {
        {{{"landuse", "grass"}}, A::Grass},           {{{"landuse", "meadow"}}, A::Grass},
        {{{"landuse", "village_green"}}, A::Grass},   {{{"landuse", "residential"}}, A::Residential},
        {{{"landuse", "commercial"}}, A::Commercial}, {{{"landuse", "retail"}}, A::Commercial},
        {{{"landuse", "industrial"}}, A::Industrial}, {{{"landuse", "railway"}}, A::Industrial},
        {{{"landuse", "forest"}}, A::Forest},         {{{"landuse", "cemetery"}}, A::Cemetery},
        {{{"landuse", "farmland"}}, A::Farmland},     {{{"landuse", "farmyard"}}, A::Farmland},
        {{{"landuse", "basin"}}, A::Water},           {{{"landuse", "reservoir"}}, A::Water},
        {{{"leisure", "park"}}, A::Park},             {{{"leisure", "garden"}}, A::Park},
        {{{"leisure", "pitch"}}, A::Pitch},           {{{"leisure", "playground"}}, A::Playground},
        {{{"natural", "water"}}, A::Water},           {{{"natural", "wetland"}}, A::Water},
        {{{"natural", "sand"}}, A::Sand},             {{{"natural", "beach"}}, A::Sand},
        {{{"natural", "scrub"}}, A::Scrub},           {{{"natural", "heath"}}, A::Scrub},
        {{{"natural", "wood"}}, A::Forest},           {{{"natural", "grassland"}}, A::Grass},
        {{{"waterway", "riverbank"}}, A::Water},      {{{"water", "pond"}}, A::Water},
        {{{"amenity", "parking"}}, A::Parking},       {{{"place", "square"}}, A::Pedestrian},
        {{{"area:highway", "footway"}}, A::Pedestrian},
        {{{"highway", "pedestrian"}, {"area", "yes"}}, A::Pedestrian},
        {{{"highway", "service"}, {"area", "yes"}}, A::Pedestrian},
        {{{"highway", "pedestrian"}, {"type", "multipolygon"}}, A::Pedestrian},
        // Priority: water, pedestrian, parking, leisure, natural, landuse.
        {{{"landuse", "grass"}, {"natural", "water"}}, A::Water},
        {{{"landuse", "residential"}, {"leisure", "park"}}, A::Park},
        {{{"landuse", "forest"}, {"natural", "scrub"}}, A::Scrub},
        {{{"leisure", "park"}, {"water", "lake"}}, A::Water},
        {{{"place", "square"}, {"leisure", "park"}}, A::Pedestrian},
        {{{"amenity", "parking"}, {"landuse", "retail"}}, A::Parking},
        // Not areas: a highway without area=yes is a road; car parks below ground; other tags.
        {{{"highway", "pedestrian"}}, std::nullopt},
        {{{"highway", "footway"}, {"leisure", "park"}}, std::nullopt},
        {{{"amenity", "parking"}, {"parking", "underground"}}, std::nullopt},
        {{{"amenity", "parking"}, {"parking", "multi-storey"}}, std::nullopt},
        {{{"shop", "bakery"}}, std::nullopt},
        {{{"landuse", "construction"}}, std::nullopt},
        {{{"place", "neighbourhood"}}, std::nullopt},
    };
    for (const auto& [tags, kind] : cases) EXPECT_EQ(areaKindFromTags(tagsOf(tags)), kind) << describe(tags);
}

TEST(StreetTagsArea, WaterwayLinesAndTheirWidths) {
    const std::vector<std::pair<Tags, std::optional<float>>> cases = {
        {{{"waterway", "river"}}, 12.0f},
        {{{"waterway", "canal"}}, 8.0f},
        {{{"waterway", "stream"}}, 3.0f},
        {{{"waterway", "drain"}}, 1.5f},
        {{{"waterway", "ditch"}}, 1.5f},
        {{{"waterway", "stream"}, {"width", "4.5"}}, 4.5f},
        {{{"waterway", "river"}, {"width", "30 m"}}, 30.0f},
        {{{"waterway", "river"}, {"width", "wide"}}, 12.0f},     // unparsable: the kind's default
        {{{"waterway", "stream"}, {"tunnel", "culvert"}}, std::nullopt},
        {{{"waterway", "stream"}, {"tunnel", "no"}}, 3.0f},
        {{{"waterway", "riverbank"}}, std::nullopt},             // an area, not a line
        {{{"waterway", "dam"}}, std::nullopt},
        {{{"natural", "water"}}, std::nullopt},
    };
    for (const auto& [tags, width] : cases) EXPECT_EQ(waterwayWidthFromTags(tagsOf(tags)), width) << describe(tags);
}

TEST(StreetTagsLamp, MountHeadHeightAndColour) {
    using M = LampMount;
    using H = LampHead;
    struct Case {
        Tags tags;
        LampMount mount;
        LampHead head;
        float height, kelvin;
    };
    const std::vector<Case> cases = {
        {{}, M::Pole, H::Cobra, 6.0f, 0.0f},
        {{{"lamp_mount", "straight_mast"}}, M::Pole, H::Cobra, 6.0f, 0.0f},
        {{{"lamp_mount", "bent_mast"}}, M::BentMast, H::Cobra, 6.0f, 0.0f},
        {{{"lamp_mount", "cast_steel"}}, M::Pole, H::Lantern, 6.0f, 0.0f},
        {{{"lamp_mount", "wall"}}, M::Wall, H::Cobra, 4.5f, 0.0f},
        {{{"lamp_mount", "wall_mounted"}}, M::Wall, H::Cobra, 4.5f, 0.0f},
        {{{"lamp_mount", "suspended"}}, M::Suspended, H::Cone, 7.0f, 0.0f},
        {{{"lamp_mount", "wire"}}, M::Suspended, H::Cone, 7.0f, 0.0f},
        {{{"lamp_mount", "ground"}}, M::Ground, H::Flat, 1.0f, 0.0f},
        {{{"support", "wall_mounted"}}, M::Wall, H::Cobra, 4.5f, 0.0f},
        {{{"support", "suspended"}}, M::Suspended, H::Cone, 7.0f, 0.0f},
        {{{"support", "ground"}}, M::Ground, H::Flat, 1.0f, 0.0f},
        {{{"support", "pole"}}, M::Pole, H::Cobra, 6.0f, 0.0f},
        {{{"lamp_mount", "bent_mast"}, {"support", "wall_mounted"}}, M::BentMast, H::Cobra, 6.0f, 0.0f},
        {{{"lamp_type", "lantern"}}, M::Pole, H::Lantern, 6.0f, 0.0f},
        {{{"lamp_type", "globe"}}, M::Pole, H::Globe, 6.0f, 0.0f},
        {{{"light:shape", "cone"}}, M::Pole, H::Cone, 6.0f, 0.0f},
        {{{"lamp_type", "floodlight"}, {"light:shape", "cone"}}, M::Pole, H::Flat, 6.0f, 0.0f},
        {{{"light:method", "high_pressure_sodium"}}, M::Pole, H::Cobra, 6.0f, 2000.0f},
        {{{"light:method", "sodium"}}, M::Pole, H::Cobra, 6.0f, 2000.0f},
        {{{"light:method", "low_pressure_sodium"}}, M::Pole, H::Cobra, 6.0f, 1800.0f},
        {{{"light:method", "mercury"}}, M::Pole, H::Cobra, 6.0f, 4000.0f},
        {{{"light:method", "metal-halide"}}, M::Pole, H::Cobra, 6.0f, 3200.0f},
        {{{"light:method", "LED"}}, M::Pole, H::Cobra, 6.0f, 4000.0f},
        {{{"light:method", "fluorescent"}}, M::Pole, H::Cobra, 6.0f, 4000.0f},
        {{{"light:method", "gas"}}, M::Pole, H::Lantern, 6.0f, 2700.0f},
        {{{"lamp_type", "incandescent"}}, M::Pole, H::Cobra, 6.0f, 2700.0f},
        {{{"light:method", "LED"}, {"light:colour", "orange"}}, M::Pole, H::Cobra, 6.0f, 2000.0f}, // colour wins
        {{{"light:method", "LED"}, {"light:colour", "3000 K"}}, M::Pole, H::Cobra, 6.0f, 3000.0f},
        {{{"lamp_mount", "wall"}, {"height", "3.2"}}, M::Wall, H::Cobra, 3.2f, 0.0f},
        {{{"height", "200"}}, M::Pole, H::Cobra, 6.0f, 0.0f},   // absurd heights ignored
    };
    for (const Case& c : cases) {
        Tags tags = c.tags;
        tags["highway"] = "street_lamp";
        const Lamp lamp = lampFromTags(tagsOf(tags), 3);
        EXPECT_EQ(lamp.mount, c.mount) << describe(tags);
        EXPECT_EQ(lamp.head, c.head) << describe(tags);
        EXPECT_FLOAT_EQ(lamp.height, c.height) << describe(tags);
        EXPECT_FLOAT_EQ(lamp.colourTemperature, c.kelvin) << describe(tags);
    }
    const Tags counted{{"highway", "street_lamp"}, {"light:count", "3"}, {"light:direction", "SW"},
                       {"lamp_type", "globe"}};
    const Lamp lamp = lampFromTags(tagsOf(counted), 4);
    EXPECT_EQ(lamp.lightCount, 3);
    EXPECT_FLOAT_EQ(lamp.direction, 225.0f);
    EXPECT_EQ(lamp.lampType, "globe");
    EXPECT_FLOAT_EQ(lampFromTags(tagsOf({{"light:direction", "90"}}), 5).direction, 90.0f);
    EXPECT_FLOAT_EQ(lampFromTags(tagsOf({{"light:direction", "up"}}), 6).direction, -1.0f);
    EXPECT_EQ(lampFromTags(tagsOf({{"light:count", "0"}}), 7).lightCount, 1);
}
