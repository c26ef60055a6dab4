#include "osm/nature_tags.h"

#include "osm/tag_parsing.h"

#include <array>
#include <string_view>

namespace urbis {

namespace {

/// `key=value` names `kind`; an empty value matches any value of the key.
struct AreaRule {
    const char* key;
    std::string_view value;
    AreaKind kind;
};
/// In priority order (see nature_tags.h).
constexpr std::array<AreaRule, 34> kAreaRules = {{
    {"natural", "water", AreaKind::Water},         {"natural", "wetland", AreaKind::Water},
    {"waterway", "riverbank", AreaKind::Water},    {"water", "", AreaKind::Water},
    {"landuse", "basin", AreaKind::Water},         {"landuse", "reservoir", AreaKind::Water},
    {"area:highway", "", AreaKind::Pedestrian},    {"place", "square", AreaKind::Pedestrian},
    {"highway", "", AreaKind::Pedestrian},         {"amenity", "parking", AreaKind::Parking},
    {"leisure", "pitch", AreaKind::Pitch},         {"leisure", "playground", AreaKind::Playground},
    {"leisure", "park", AreaKind::Park},           {"leisure", "garden", AreaKind::Park},
    {"natural", "sand", AreaKind::Sand},           {"natural", "beach", AreaKind::Sand},
    {"natural", "scrub", AreaKind::Scrub},         {"natural", "heath", AreaKind::Scrub},
    {"natural", "wood", AreaKind::Forest},         {"natural", "grassland", AreaKind::Grass},
    {"landuse", "forest", AreaKind::Forest},       {"landuse", "cemetery", AreaKind::Cemetery},
    {"landuse", "grass", AreaKind::Grass},         {"landuse", "meadow", AreaKind::Grass},
    {"landuse", "village_green", AreaKind::Grass}, {"landuse", "farmland", AreaKind::Farmland},
    {"landuse", "farmyard", AreaKind::Farmland},   {"landuse", "residential", AreaKind::Residential},
    {"landuse", "commercial", AreaKind::Commercial}, {"landuse", "retail", AreaKind::Commercial},
    {"landuse", "industrial", AreaKind::Industrial}, {"landuse", "railway", AreaKind::Industrial},
    {"amenity", "grave_yard", AreaKind::Cemetery}, {"leisure", "dog_park", AreaKind::Park}}};

bool is(const char* value, std::string_view name) { return value && trim(value) == name; }

/// A highway is an area only with area=yes, or as a multipolygon; otherwise it is a road.
bool isHighwayArea(const TagLookup& tag) { return is(tag("area"), "yes") || is(tag("type"), "multipolygon"); }

/// Whether the rule's tag, present on the object, may stand for an area: a highway only as an
/// area (area=yes, or a multipolygon), a car park only at ground level.
bool applies(const AreaRule& rule, const TagLookup& tag) {
    const std::string_view key = rule.key;
    if (key == "highway") return isHighwayArea(tag);
    if (key == "amenity" && rule.kind == AreaKind::Parking) {
        const char* parking = tag("parking");
        return !is(parking, "underground") && !is(parking, "multi-storey");
    }
    return true;
}

} // namespace

Tree treeFromTags(const TagLookup& tag, int64_t osmId) {
    Tree tree;
    tree.osmId = osmId;
    if (const char* height = tag("height"))
        if (const std::optional<double> h = parseLength(height); h && *h > 0.5 && *h < 150.0)
            tree.height = float(*h), tree.heightTagged = true;
    if (const char* crown = tag("diameter_crown"))
        if (const std::optional<double> d = parseLength(crown); d && *d > 0.2 && *d < 80.0)
            tree.crownDiameter = float(*d), tree.crownTagged = true;
    if (const char* girth = tag("circumference"))
        if (const std::optional<double> c = parseLength(girth); c && *c > 0.05 && *c < 30.0) tree.circumference = float(*c);
    tree.leafType = leafTypeFromTags(tag);
    if (is(tag("leaf_cycle"), "deciduous") || is(tag("leaf_cycle"), "semi_deciduous")) tree.leafCycle = LeafCycle::Deciduous;
    if (is(tag("leaf_cycle"), "evergreen") || is(tag("leaf_cycle"), "semi_evergreen")) tree.leafCycle = LeafCycle::Evergreen;
    return tree;
}

LeafType leafTypeFromTags(const TagLookup& tag) {
    if (is(tag("leaf_type"), "broadleaved")) return LeafType::Broadleaved;
    if (is(tag("leaf_type"), "needleleaved")) return LeafType::Needleleaved;
    return LeafType::Unknown;
}

std::optional<float> waterwayWidthFromTags(const TagLookup& tag) {
    static constexpr std::array<std::pair<std::string_view, float>, 5> kWidths = {
        {{"river", 12.0f}, {"canal", 8.0f}, {"stream", 3.0f}, {"drain", 1.5f}, {"ditch", 1.5f}}};
    const char* waterway = tag("waterway");
    if (!waterway) return std::nullopt;
    if (const char* tunnel = tag("tunnel"); tunnel && std::string_view(tunnel) != "no") return std::nullopt;
    for (const auto& [kind, width] : kWidths) {
        if (kind != waterway) continue;
        const char* tagged = tag("width");
        const std::optional<double> metres = tagged ? parseLength(tagged) : std::nullopt;
        return metres && *metres > 0.1 ? float(*metres) : width;
    }
    return std::nullopt;
}

std::optional<AreaKind> areaKindFromTags(const TagLookup& tag) {
    if (tag("highway") && !isHighwayArea(tag)) return std::nullopt;
    for (const AreaRule& rule : kAreaRules) {
        const char* value = tag(rule.key);
        if (value && (rule.value.empty() || trim(value) == rule.value) && applies(rule, tag)) return rule.kind;
    }
    return std::nullopt;
}

} // namespace urbis
