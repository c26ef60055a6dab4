#include "osm/building_tags.h"

#include "osm/building_use.h"
#include "osm/colour_table.h"
#include "osm/tag_parsing.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace urbis {

namespace {

uint64_t splitmix64(uint64_t x) {
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

/// Reads one tag with `parse`; a present but unparsable value counts as `badReason`.
template <typename Parse>
auto readTag(const TagLookup& tag, const char* key, Parse parse, const char* badReason,
             std::map<std::string, uint64_t>& issues) -> decltype(parse("")) {
    const char* value = tag(key);
    if (!value) return std::nullopt;
    auto parsed = parse(value);
    if (!parsed) ++issues[badReason];
    return parsed;
}

} // namespace

uint32_t objectSeed(uint32_t seed, int64_t osmId) {
    return uint32_t(splitmix64(splitmix64(seed) ^ uint64_t(osmId)) >> 32);
}

Building buildingFromTags(const TagLookup& tag, const ImportOptions& options, int64_t osmId,
                          std::map<std::string, uint64_t>& issues) {
    Building b;
    b.osmId = osmId;
    b.seed = objectSeed(options.seed, osmId);
    const float perLevel = options.metresPerLevel;

    const std::optional<double> heightTag = readTag(tag, "height", parseLength, "bad_height_tag", issues);
    const double height = heightTag.value_or(0.0); // 0: untagged or unusable
    if (heightTag && height <= 0.0) ++issues["bad_height_tag"];
    const auto minHeight = readTag(tag, "min_height", parseLength, "bad_min_height_tag", issues);
    const auto roofHeight = readTag(tag, "roof:height", parseLength, "bad_roof_height_tag", issues);
    const auto levels = readTag(tag, "building:levels", parseLevels, "bad_levels_tag", issues);
    const auto roofLevels = readTag(tag, "roof:levels", parseLevels, "bad_levels_tag", issues);
    const auto minLevel = readTag(tag, "building:min_level", parseLevels, "bad_levels_tag", issues);

    const char* shape = tag("roof:shape");
    b.roofShape = shape ? parseRoofShape(shape) : RoofShape::Flat;
    b.levels = levels ? int(std::lround(*levels)) : -1;
    b.roofLevels = roofLevels ? int(std::lround(*roofLevels)) : 0;
    b.minLevel = minLevel ? int(std::lround(*minLevel)) : 0;
    b.minHeight = float(minHeight ? *minHeight : b.minLevel * perLevel);

    // Untagged, a sloped roof is guessed one storey tall for the building's height, and its own
    // height is left 0 for the roof mesher to derive from roof:angle or the footprint.
    float roof = 0.0f;
    if (roofHeight) roof = float(*roofHeight);
    else if (roofLevels) roof = float(*roofLevels) * perLevel;
    const float roofGuess = roof > 0.0f || b.roofShape == RoofShape::Flat ? roof : perLevel;

    if (height > 0.0) {
        b.height = float(height);
        b.heightSource = HeightSource::HeightTag;
    } else if (levels) {
        b.height = float(*levels) * perLevel + roofGuess;
        b.heightSource = HeightSource::Levels;
    } else {
        // Neighbours and region are unknown until the whole file is read: estimateHeights
        // replaces this one storey under the roof, which only keeps a tagged roof unclamped.
        b.height = b.minHeight + roofGuess + perLevel;
        b.heightSource = HeightSource::TypeTable;
    }
    if (b.minHeight >= b.height) {
        ++issues["bad_min_height_tag"];
        b.minHeight = 0.0f;
    }
    b.roofHeight = std::clamp(roof, 0.0f, b.height - b.minHeight);

    if (const auto angle = readTag(tag, "roof:angle", parseAngle, "bad_roof_angle_tag", issues)) b.roofAngle = *angle;
    if (const char* direction = tag("roof:direction")) {
        const std::optional<float> degrees = parseDirection(direction);
        if (degrees) b.roofDirection = *degrees;
        else ++issues["bad_roof_direction_tag"];
    }
    if (const char* orientation = tag("roof:orientation")) b.roofAcross = std::string_view(orientation) == "across";

    b.type = buildingTypeFromTags(tag);
    const char* material = tag("building:material");
    b.material = material ? parseMaterial(material) : BuildingMaterial::Unknown;

    // Colours no tag sets are left to paintUntaggedBuildings, which knows the city's region.
    std::optional<Rgb> wallTagged = materialColour(b.material), roofTagged;
    if (const char* roofMaterial = tag("roof:material")) roofTagged = roofMaterialColour(roofMaterial);
    if (const auto c = readTag(tag, "building:colour", parseColour, "bad_colour_tag", issues)) wallTagged = c;
    if (const auto c = readTag(tag, "roof:colour", parseColour, "bad_colour_tag", issues)) roofTagged = c;
    b.wallColourTagged = wallTagged.has_value();
    b.roofColourTagged = roofTagged.has_value();
    b.wallColour = wallTagged.value_or(b.wallColour);
    b.roofColour = roofTagged.value_or(b.roofColour);
    return b;
}

} // namespace urbis
