// Colours of buildings: roof:material values, the order tag > material > palette, and the
// regional palettes' variety (buildingFromTags, then paintUntaggedBuildings as importOsm runs them).
#include "osm/building_palette.h"
#include "osm/building_tags.h"
#include "osm/colour_table.h"

#include "tag_map.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <tuple>

using namespace urbis;
using test::tagsOf;

namespace {

/// What a colour looks like, coarsely: enough to say a material's colour is the right kind.
enum class Look { Red, Grey, Dark, Light, Green, Blue };

Look lookOf(Rgb c) {
    const float hi = std::max({c.r, c.g, c.b}), lo = std::min({c.r, c.g, c.b});
    const float luminance = 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;
    if (hi - lo < 0.35f * hi) return luminance < 0.06f ? Look::Dark : luminance > 0.4f ? Look::Light : Look::Grey;
    if (c.r == hi) return Look::Red;
    return c.g == hi ? Look::Green : Look::Blue;
}

/// Linear saturation (max - min) / max.
float saturation(Rgb c) {
    const float hi = std::max({c.r, c.g, c.b}), lo = std::min({c.r, c.g, c.b});
    return hi > 0.0f ? (hi - lo) / hi : 0.0f;
}

/// `n` buildings of one tag set, ids 1..n, painted as importOsm paints a city at (lon, lat).
std::vector<Building> city(const std::map<std::string, std::string>& tags, int n, double lon, double lat) {
    CityModel model;
    model.origin = {true, lat, lon};
    std::map<std::string, uint64_t> issues;
    for (int id = 1; id <= n; ++id) model.buildings.push_back(buildingFromTags(tagsOf(tags), {}, id, issues));
    paintUntaggedBuildings(model);
    return model.buildings;
}

size_t distinct(const std::vector<Building>& buildings, bool roof) {
    std::set<std::tuple<float, float, float>> colours;
    for (const Building& b : buildings) {
        const Rgb c = roof ? b.roofColour : b.wallColour;
        colours.insert({c.r, c.g, c.b});
    }
    return colours.size();
}

constexpr double kBerlin[] = {13.43, 52.48}, kLondon[] = {-0.09, 51.51}, kMoscow[] = {37.63, 55.76},
                 kSanFrancisco[] = {-122.40, 37.79}, kRome[] = {12.48, 41.89}, kTokyo[] = {139.7, 35.7};

} // namespace

TEST(BuildingPalette, RoofMaterialTable) {
    const std::pair<const char*, Look> rows[] = {
        {"roof_tiles", Look::Red}, {"tile", Look::Red},     {"tiles", Look::Red},      {"clay", Look::Red},
        {"slate", Look::Grey},     {"metal", Look::Grey},   {"metal_sheet", Look::Grey}, {"zinc", Look::Grey},
        {"lead", Look::Grey},      {"copper", Look::Green}, {"concrete", Look::Grey},  {"gravel", Look::Grey},
        {"tar_paper", Look::Dark}, {"asphalt", Look::Dark}, {"bitumen", Look::Dark},   {"asphalt_shingle", Look::Grey},
        {"glass", Look::Blue},     {"acrylic_glass", Look::Blue}, {"grass", Look::Green}, {"plants", Look::Green},
        {"eternit", Look::Grey},   {"asbestos", Look::Grey}, {"thatch", Look::Red},    {"stone", Look::Grey},
        {"wood", Look::Red},       {"plastic", Look::Light}, {"membrane", Look::Light}, {"solar_panels", Look::Blue}};
    for (const auto& [value, look] : rows) {
        const std::optional<Rgb> c = roofMaterialColour(value);
        ASSERT_TRUE(c.has_value()) << value;
        EXPECT_EQ(lookOf(*c), look) << value;
    }
    for (const char* value : {"galss", "", "Roof_Tiles", "yes"}) EXPECT_FALSE(roofMaterialColour(value)) << value;
    EXPECT_LT(roofMaterialColour("slate")->g, roofMaterialColour("concrete")->g);
}

TEST(BuildingPalette, ColourTagWinsOverMaterialWinsOverPalette) {
    const auto roofOf = [](const std::map<std::string, std::string>& tags) {
        return city(tags, 1, kBerlin[0], kBerlin[1])[0].roofColour;
    };
    const Rgb tagged = roofOf({{"building", "house"}, {"roof:colour", "#336699"}, {"roof:material", "slate"}});
    EXPECT_FLOAT_EQ(tagged.b, parseColour("#336699")->b);
    const Rgb material = roofOf({{"building", "house"}, {"roof:material", "copper"}});
    EXPECT_FLOAT_EQ(material.g, roofMaterialColour("copper")->g);
    const Rgb palette = roofOf({{"building", "house"}, {"roof:material", "unobtainium"}});
    EXPECT_NE(palette.g, material.g);
    const Building wall = city({{"building", "yes"}, {"building:colour", "white"}, {"building:material", "brick"}}, 1,
                               kBerlin[0], kBerlin[1])[0];
    EXPECT_FLOAT_EQ(wall.wallColour.g, 1.0f);
    const Building brick = city({{"building", "yes"}, {"building:material", "brick"}}, 1, kBerlin[0], kBerlin[1])[0];
    EXPECT_FLOAT_EQ(brick.wallColour.r, materialColour(BuildingMaterial::Brick)->r);
}

TEST(BuildingPalette, UntaggedBuildingsVaryAndFlatRoofsAreNotRed) {
    const double* places[] = {kBerlin, kLondon, kMoscow, kSanFrancisco, kRome, kTokyo};
    for (const double* at : places) {
        const auto flats = city({{"building", "residential"}}, 100, at[0], at[1]);
        EXPECT_GE(distinct(flats, true), 6u) << at[0];
        EXPECT_GE(distinct(flats, false), 6u) << at[0];
        for (const Building& b : flats) {
            ASSERT_EQ(b.roofShape, RoofShape::Flat);
            EXPECT_LT(saturation(b.roofColour), 0.25f) << at[0]; // gravel, bitumen, membrane: greys
        }
        const auto houses = city({{"building", "house"}, {"roof:shape", "gabled"}}, 100, at[0], at[1]);
        EXPECT_GE(distinct(houses, true), 6u) << at[0];
        for (const Building& b : houses) EXPECT_LT(saturation(b.roofColour), 0.9f) << at[0];
    }
    // Central European pitched roofs: mostly clay reds and browns, some dark grey tiles.
    const auto berlin = city({{"building", "house"}, {"roof:shape", "hipped"}}, 200, kBerlin[0], kBerlin[1]);
    const auto reds = std::count_if(berlin.begin(), berlin.end(), [](const Building& b) {
        return lookOf(b.roofColour) == Look::Red;
    });
    EXPECT_GT(reds, 100);
    EXPECT_LT(reds, 190);
    // North American ones are shingle greys and browns, never clay red.
    for (const Building& b : city({{"building", "house"}, {"roof:shape", "gabled"}}, 100, kSanFrancisco[0], kSanFrancisco[1]))
        EXPECT_LT(saturation(b.roofColour), 0.5f);
}

TEST(BuildingPalette, SameSeedSameColoursAndRegionsFromOrigin) {
    const auto a = city({{"building", "apartments"}}, 20, kLondon[0], kLondon[1]);
    const auto b = city({{"building", "apartments"}}, 20, kLondon[0], kLondon[1]);
    for (size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].wallColour.r, b[i].wallColour.r);
        EXPECT_EQ(a[i].roofColour.g, b[i].roofColour.g);
    }
    const auto region = [](const double* at) { return paletteRegionOf({true, at[1], at[0]}); };
    EXPECT_EQ(region(kBerlin), PaletteRegion::CentralEurope);
    EXPECT_EQ(region(kLondon), PaletteRegion::BritishIsles);
    EXPECT_EQ(region(kMoscow), PaletteRegion::EasternEurope);
    EXPECT_EQ(region(kSanFrancisco), PaletteRegion::NorthAmerica);
    EXPECT_EQ(region(kRome), PaletteRegion::SouthernEurope);
    EXPECT_EQ(region(kTokyo), PaletteRegion::Other);
    EXPECT_EQ(paletteRegionOf({}), PaletteRegion::Other);
}
