// Table-driven tag parsing, apart from any geometry or file.
#include "osm/building_tags.h"
#include "osm/colour_table.h"
#include "osm/lamp_tags.h"
#include "osm/nature_tags.h"
#include "osm/street_tags.h"
#include "osm/tag_parsing.h"

#include "tag_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <string>

using namespace urbis;

using test::tagsOf;

TEST(TagParsing, LengthWithUnits) {
    const std::pair<const char*, double> cases[] = {
        {"12", 12.0},        {"12 m", 12.0},      {"12.5m", 12.5},      {"12,5", 12.5},
        {" 7 metres ", 7.0}, {"40'", 12.192},     {"40 ft", 12.192},    {"40ft", 12.192},
        {"40'6\"", 12.3444}, {"40' 6\"", 12.3444}, {"0", 0.0},          {"1000", 1000.0}};
    for (const auto& [text, metres] : cases) {
        const std::optional<double> parsed = parseLength(text);
        ASSERT_TRUE(parsed.has_value()) << text;
        EXPECT_NEAR(*parsed, metres, 1e-9) << text;
    }
}

TEST(TagParsing, BadLengthsAreMissing) {
    for (const char* text : {"-5", "1e30", "NaN", "nan", "inf", "-inf", "tall", "", "12;15", "12 km",
                             "1001", "12 m high", "'6", "40'x"})
        EXPECT_FALSE(parseLength(text).has_value()) << text;
}

TEST(TagParsing, ElevationsAboveSeaLevel) {
    EXPECT_EQ(parseElevation("12"), 12.0);
    EXPECT_EQ(parseElevation("12,5 m"), 12.5);
    EXPECT_EQ(parseElevation("-28"), -28.0);
    EXPECT_NEAR(*parseElevation("1000 ft"), 304.8, 1e-9);
    for (const char* text : {"", "high", "12 km", "12;15", "9001", "-501", "nan", "inf", "12 m high"})
        EXPECT_FALSE(parseElevation(text).has_value()) << text;
}

TEST(TagParsing, LevelsDirectionsAndTemperatures) {
    EXPECT_EQ(parseLevels("3"), 3.0);
    EXPECT_EQ(parseLevels("2,5"), 2.5);
    EXPECT_FALSE(parseLevels("-1").has_value());
    EXPECT_FALSE(parseLevels("3 m").has_value());
    EXPECT_FALSE(parseLevels("9999").has_value());
    EXPECT_EQ(parseInteger("-1"), -1);
    EXPECT_FALSE(parseInteger("1.5").has_value());
    EXPECT_EQ(parseDirection("SW"), 225.0f);
    EXPECT_EQ(parseDirection("NNE"), 22.5f);
    EXPECT_EQ(parseDirection("-90"), 270.0f);
    EXPECT_FALSE(parseDirection("up").has_value());
    EXPECT_EQ(parseColourTemperature("3000 K"), 3000.0f);
    EXPECT_EQ(parseColourTemperature("orange"), 2000.0f);
    EXPECT_FALSE(parseColourTemperature("50").has_value());
}

TEST(TagParsing, EnumTables) {
    EXPECT_EQ(parseRoofShape("gabled"), RoofShape::Gabled);
    EXPECT_EQ(parseRoofShape("half-hipped"), RoofShape::Hipped);
    EXPECT_EQ(parseRoofShape("wavy"), RoofShape::Unknown);
    EXPECT_EQ(parseBuildingType("apartments"), BuildingType::Apartments);
    EXPECT_EQ(parseBuildingType("cathedral"), BuildingType::Religious);
    EXPECT_EQ(parseBuildingType("yes"), BuildingType::Generic);
    EXPECT_EQ(parseMaterial("brick"), BuildingMaterial::Brick);
    EXPECT_EQ(parseMaterial("timber_framing"), BuildingMaterial::Timber);
    EXPECT_EQ(parseHighwayClass("primary_link"), HighwayClass::Primary);
    EXPECT_EQ(parseHighwayClass("bus_stop"), HighwayClass::Other);
    EXPECT_EQ(parseSidewalk("both"), Sidewalk::Both);
    EXPECT_EQ(parseSidewalk("separate"), Sidewalk::Separate);
}

TEST(ColourTable, NamesAndHexAreLinear) {
    const std::optional<Rgb> red = parseColour("red");
    ASSERT_TRUE(red.has_value());
    EXPECT_FLOAT_EQ(red->r, 1.0f);
    EXPECT_FLOAT_EQ(red->g, 0.0f);
    const std::optional<Rgb> grey = parseColour("Grey");
    ASSERT_TRUE(grey.has_value());
    EXPECT_NEAR(grey->r, 0.2158605f, 1e-5); // sRGB 128/255 -> linear
    const std::optional<Rgb> shortHex = parseColour("#fa0"), longHex = parseColour("#FFAA00");
    ASSERT_TRUE(shortHex && longHex);
    EXPECT_FLOAT_EQ(shortHex->g, longHex->g);
    EXPECT_NEAR(longHex->g, linearFromSrgb(170.0f / 255.0f), 1e-6);
    EXPECT_TRUE(parseColour("light_yellow").has_value()); // CSS name written OSM-style
    EXPECT_TRUE(parseColour("yellow-brown").has_value()); // OSM's own name
    EXPECT_FALSE(parseColour("#12345").has_value());
    EXPECT_FALSE(parseColour("#gg0000").has_value());
    EXPECT_FALSE(parseColour("sky").has_value());
    EXPECT_NEAR(linearFromSrgb(0.5f), 0.2140411f, 1e-6);
}

TEST(BuildingTags, HeightFromTagOrLevelsElseLeftToEstimate) {
    ImportOptions options;
    std::map<std::string, uint64_t> issues;
    const std::map<std::string, std::string> tagged{{"building", "office"}, {"height", "40'"}, {"min_height", "3 m"}};
    const Building a = buildingFromTags(tagsOf(tagged), options, 7, issues);
    EXPECT_EQ(a.heightSource, HeightSource::HeightTag);
    EXPECT_NEAR(a.height, 12.192f, 1e-4f);
    EXPECT_FLOAT_EQ(a.minHeight, 3.0f);
    EXPECT_EQ(a.type, BuildingType::Office);

    const std::map<std::string, std::string> levels{{"building", "house"}, {"building:levels", "4"},
                                                    {"roof:levels", "1"}, {"roof:shape", "gabled"}};
    const Building b = buildingFromTags(tagsOf(levels), options, 8, issues);
    EXPECT_EQ(b.heightSource, HeightSource::Levels);
    EXPECT_FLOAT_EQ(b.height, 15.0f); // (4 + 1) x 3 m
    EXPECT_FLOAT_EQ(b.roofHeight, 3.0f);
    EXPECT_EQ(b.roofShape, RoofShape::Gabled);
    EXPECT_TRUE(issues.empty());

    // Untagged: a placeholder one storey under the roof, for estimateHeights to replace.
    const std::map<std::string, std::string> untagged{{"building", "yes"}, {"roof:height", "5"}};
    const Building c1 = buildingFromTags(tagsOf(untagged), options, 12345, issues);
    const Building c2 = buildingFromTags(tagsOf(untagged), options, 12345, issues);
    const Building d = buildingFromTags(tagsOf(untagged), options, 12346, issues);
    EXPECT_EQ(c1.heightSource, HeightSource::TypeTable);
    EXPECT_FALSE(isTagged(c1.heightSource));
    EXPECT_FLOAT_EQ(c1.height, 5.0f + options.metresPerLevel);
    EXPECT_FLOAT_EQ(c1.roofHeight, 5.0f);
    EXPECT_EQ(c1.seed, c2.seed);
    EXPECT_NE(c1.seed, d.seed);
}

TEST(BuildingTags, BadHeightIsCountedAndLeftToEstimate) {
    ImportOptions options;
    for (const char* bad : {"-5", "1e30", "NaN", "tall", "0"}) {
        std::map<std::string, uint64_t> issues;
        const std::map<std::string, std::string> tags{{"building", "yes"}, {"height", bad}};
        const Building b = buildingFromTags(tagsOf(tags), options, 1, issues);
        EXPECT_EQ(issues["bad_height_tag"], 1u) << bad;
        EXPECT_EQ(b.heightSource, HeightSource::TypeTable) << bad;
        EXPECT_TRUE(std::isfinite(b.height)) << bad;
    }
}

TEST(BuildingTags, ColoursFromTagOrMaterialElseUntagged) {
    ImportOptions options;
    std::map<std::string, uint64_t> issues;
    const std::map<std::string, std::string> tagged{{"building", "yes"}, {"building:colour", "white"},
                                                    {"roof:colour", "#800000"}, {"roof:material", "slate"},
                                                    {"building:material", "brick"}};
    const Building a = buildingFromTags(tagsOf(tagged), options, 1, issues);
    EXPECT_FLOAT_EQ(a.wallColour.g, 1.0f);
    EXPECT_NEAR(a.roofColour.r, linearFromSrgb(128.0f / 255.0f), 1e-6);
    EXPECT_TRUE(a.wallColourTagged && a.roofColourTagged);
    const std::map<std::string, std::string> brick{{"building", "church"}, {"building:material", "brick"},
                                                   {"roof:material", "thatch-ish"}};
    const Building b = buildingFromTags(tagsOf(brick), options, 1, issues);
    EXPECT_EQ(b.material, BuildingMaterial::Brick);
    EXPECT_FLOAT_EQ(b.wallColour.r, materialColour(BuildingMaterial::Brick)->r);
    EXPECT_TRUE(b.wallColourTagged);
    EXPECT_FALSE(b.roofColourTagged); // an unlisted material leaves the roof to the palette
    const std::map<std::string, std::string> bad{{"building", "yes"}, {"building:colour", "sky"}};
    buildingFromTags(tagsOf(bad), options, 1, issues);
    EXPECT_EQ(issues["bad_colour_tag"], 1u);
}

TEST(StreetTags, RoadWidthLanesAndFlags) {
    std::map<std::string, uint64_t> issues;
    bool reversed = false;
    const std::map<std::string, std::string> wide{{"highway", "primary"}, {"width", "30 ft"}, {"lanes", "4"},
                                                  {"bridge", "yes"}, {"layer", "1"}, {"sidewalk", "both"}};
    const Road a = roadFromTags(tagsOf(wide), 1, reversed, issues);
    EXPECT_EQ(a.highway, HighwayClass::Primary);
    EXPECT_NEAR(a.width, 9.144f, 1e-4f);
    EXPECT_EQ(a.lanes, 4);
    EXPECT_TRUE(a.bridge);
    EXPECT_EQ(a.layer, 1);
    EXPECT_EQ(a.sidewalk, Sidewalk::Both);
    EXPECT_FALSE(reversed);

    const std::map<std::string, std::string> lanes{{"highway", "residential"}, {"lanes", "3"}, {"oneway", "-1"}};
    const Road b = roadFromTags(tagsOf(lanes), 2, reversed, issues);
    EXPECT_FLOAT_EQ(b.width, 3 * 3.0f); // a residential lane is 3 m
    EXPECT_TRUE(b.oneway);
    EXPECT_TRUE(reversed);

    const std::map<std::string, std::string> bad{{"highway", "service"}, {"width", "wide"}};
    const Road c = roadFromTags(tagsOf(bad), 3, reversed, issues);
    EXPECT_EQ(issues["road_bad_width_tag"], 1u);
    EXPECT_GT(c.width, 0.0f);
}

TEST(StreetTags, LampsAndTrees) {
    const std::map<std::string, std::string> lampTags{{"highway", "street_lamp"}, {"height", "8"},
                                                      {"light:method", "LED"}, {"light:count", "2"},
                                                      {"light:colour", "white"}};
    const Lamp lamp = lampFromTags(tagsOf(lampTags), 5);
    EXPECT_FLOAT_EQ(lamp.height, 8.0f);
    EXPECT_EQ(lamp.lampType, "LED");
    EXPECT_EQ(lamp.lightCount, 2);
    EXPECT_FLOAT_EQ(lamp.colourTemperature, 4000.0f);
    const std::map<std::string, std::string> treeTags{{"natural", "tree"}, {"height", "12 m"}, {"diameter_crown", "6"}};
    const Tree tree = treeFromTags(tagsOf(treeTags), 6);
    EXPECT_FLOAT_EQ(tree.height, 12.0f);
    EXPECT_FLOAT_EQ(tree.crownDiameter, 6.0f);
    const std::map<std::string, std::string> park{{"leisure", "park"}}, river{{"waterway", "riverbank"}},
        shop{{"shop", "bakery"}};
    EXPECT_EQ(areaKindFromTags(tagsOf(park)), AreaKind::Park);
    EXPECT_EQ(areaKindFromTags(tagsOf(river)), AreaKind::Water);
    EXPECT_FALSE(areaKindFromTags(tagsOf(shop)).has_value());
}

TEST(BuildingTags, RoofTagsReachTheBuilding) {
    ImportOptions options;
    std::map<std::string, uint64_t> issues;
    const std::map<std::string, std::string> tagged{{"building", "house"}, {"height", "12"}, {"roof:shape", "hipped"},
                                                    {"roof:angle", "35°"}, {"roof:direction", "SW"},
                                                    {"roof:orientation", "across"}};
    const Building a = buildingFromTags(tagsOf(tagged), options, 1, issues);
    EXPECT_EQ(a.roofShape, RoofShape::Hipped);
    EXPECT_FLOAT_EQ(a.roofAngle, 35.0f);
    EXPECT_FLOAT_EQ(a.roofDirection, 225.0f);
    EXPECT_TRUE(a.roofAcross);
    EXPECT_FLOAT_EQ(a.roofHeight, 0.0f);  // untagged: the roof mesher derives it from the angle
    EXPECT_TRUE(issues.empty());

    const std::map<std::string, std::string> height{{"building", "yes"}, {"height", "12"}, {"roof:shape", "gabled"},
                                                    {"roof:height", "4.5 m"}, {"roof:angle", "95"}};
    const Building b = buildingFromTags(tagsOf(height), options, 2, issues);
    EXPECT_FLOAT_EQ(b.roofHeight, 4.5f);
    EXPECT_FLOAT_EQ(b.roofAngle, -1.0f);
    EXPECT_EQ(issues["bad_roof_angle_tag"], 1u);
    EXPECT_FLOAT_EQ(parseAngle("40 deg").value_or(0), 40.0f);
}
