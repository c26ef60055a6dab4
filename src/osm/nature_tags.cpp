#include "osm/nature_tags.h"

#include "osm/tag_parsing.h"

#include <array>
#include <string_view>

namespace urbis {

namespace {

struct AreaRule {
    const char* key;
    std::string_view value;
    AreaKind kind;
};
constexpr std::array<AreaRule, 8> kAreaRules = {{
    {"leisure", "park", AreaKind::Park},    {"leisure", "garden", AreaKind::Park},
    {"landuse", "grass", AreaKind::Grass},  {"landuse", "meadow", AreaKind::Grass},
    {"landuse", "forest", AreaKind::Forest}, {"natural", "wood", AreaKind::Forest},
    {"natural", "water", AreaKind::Water},  {"waterway", "riverbank", AreaKind::Water}}};

} // namespace

Tree treeFromTags(const TagLookup& tag, int64_t osmId) {
    Tree tree;
    tree.osmId = osmId;
    if (const char* height = tag("height"))
        if (const std::optional<double> h = parseLength(height); h && *h > 0.5 && *h < 150.0)
            tree.height = float(*h);
    if (const char* crown = tag("diameter_crown"))
        if (const std::optional<double> d = parseLength(crown); d && *d > 0.2 && *d < 80.0)
            tree.crownDiameter = float(*d);
    return tree;
}

std::optional<AreaKind> areaKindFromTags(const TagLookup& tag) {
    for (const AreaRule& rule : kAreaRules)
        if (const char* value = tag(rule.key); value && rule.value == value) return rule.kind;
    return std::nullopt;
}

} // namespace urbis
