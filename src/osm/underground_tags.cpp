#include "osm/underground_tags.h"

#include "osm/tag_parsing.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <optional>
#include <string_view>

namespace urbis {

namespace {

/// Whether f(item) holds for every item of a ';'-separated OSM list, blanks trimmed (stops
/// at the first item it fails on).
template <typename F>
bool allItems(std::string_view list, F&& f) {
    for (;;) {
        const size_t end = list.find(';');
        if (!f(trim(list.substr(0, end)))) return false;
        if (end == std::string_view::npos) return true;
        list.remove_prefix(end + 1);
    }
}

/// Reads a signed decimal number at the start of `s` and moves past it.
std::optional<double> takeSigned(std::string_view& s) {
    double v = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc()) return std::nullopt;
    s.remove_prefix(size_t(end - s.data()));
    return v;
}

/// One `level` item below ground: "-1", "-0.9", or a range whose both ends are ("-1--3").
/// Unparsable items are not evidence (false).
bool itemBelowGround(std::string_view item) {
    const std::optional<double> first = takeSigned(item);
    if (!first) return false;
    if (item.empty()) return *first < 0.0;
    if (item.front() != '-') return false;
    item.remove_prefix(1);
    const std::optional<double> last = takeSigned(item);
    return last && item.empty() && *first < 0.0 && *last < 0.0;
}

bool levelsBelowGround(std::string_view value, const TagLookup&) { return allItems(value, itemBelowGround); }

bool locationUnderground(std::string_view value, const TagLookup&) {
    bool underground = false;
    allItems(value, [&](std::string_view item) {
        underground = underground || item == "underground";
        return true;
    });
    return underground;
}

bool tunnel(std::string_view value, const TagLookup&) {
    return !oneOf(value, {"no", "building_passage", "avalanche_protector"});
}

bool noLevelsAboveGround(std::string_view value, const TagLookup& tag) {
    const char* levels = tag("building:levels");
    const std::optional<double> underground = parseLevels(value);
    return levels && parseLevels(levels) == 0.0 && underground && *underground >= 1.0;
}

bool undergroundValue(std::string_view value, const TagLookup&) { return value == "underground"; }

/// parking=underground says where a car park is; on a building of another use (apartments
/// with parking=underground) it describes the building's car park, not the building.
bool undergroundCarPark(std::string_view value, const TagLookup& tag) {
    if (value != "underground") return false;
    if (const char* amenity = tag("amenity"); amenity && std::string_view(amenity) == "parking") return true;
    const char* building = tag("building");
    if (!building) building = tag("building:part");
    return building && oneOf(building, {"yes", "parking", "garage", "garages"});
}

struct Rule {
    const char* key;
    bool (*says)(std::string_view value, const TagLookup& tag);
};

constexpr std::array<Rule, 10> kRules = {{
    {"location", locationUnderground},
    {"tunnel", tunnel},
    {"level", levelsBelowGround},
    {"building:level", levelsBelowGround},
    {"max_level", levelsBelowGround},
    {"building:max_level", levelsBelowGround},
    {"building:levels:underground", noLevelsAboveGround},
    {"building", undergroundValue},
    {"building:part", undergroundValue},
    {"parking", undergroundCarPark},
}};

/// location values that put the object above ground whatever else it says.
bool locatedAboveGround(const TagLookup& tag) {
    const char* location = tag("location");
    return location && !allItems(location, [](std::string_view item) {
        return !oneOf(item, {"surface", "overground", "overhead", "roof", "rooftop"});
    });
}

} // namespace

bool isUnderground(const TagLookup& tag) {
    if (locatedAboveGround(tag)) return false;
    return std::any_of(kRules.begin(), kRules.end(), [&](const Rule& rule) {
        const char* value = tag(rule.key);
        return value && rule.says(trim(value), tag);
    });
}

} // namespace urbis
