// Pure parsers of OSM tag values: numbers with units, counts, directions and the tables
// that map tag values to model enums. No geometry, no libosmium: tested on their own.
#pragma once

#include "model/city_model.h"

#include <initializer_list>
#include <optional>
#include <string_view>

namespace urbis {

/// `s` without leading and trailing blanks (spaces, tabs, line ends).
std::string_view trim(std::string_view s);

/// Whether `s` equals one of `names`.
bool oneOf(std::string_view s, std::initializer_list<std::string_view> names);

/// A length in metres from values like "12", "12 m", "12.5m", "12,5", "40'", "40 ft",
/// "40'6\"". Negative, NaN, infinite, absurd (> 1000 m) or unparsable values give nullopt.
std::optional<double> parseLength(std::string_view value);

/// A height above sea level in metres (`ele`) from "12", "12.5 m", "-28", "1200 ft": nullopt for
/// anything unparsable or beyond [-500, 9000] m (no water lies lower or higher on Earth).
std::optional<double> parseElevation(std::string_view value);

/// A storey count ("3", "2.5"), in [0, 300]; anything else gives nullopt.
std::optional<double> parseLevels(std::string_view value);

/// A roof:angle in degrees from horizontal: "35", "35°", "35 deg"; nothing outside (0, 90).
std::optional<float> parseAngle(std::string_view value);

/// A whole number ("-1", "4"); anything else gives nullopt.
std::optional<int> parseInteger(std::string_view value);

/// A compass direction in degrees clockwise from north, [0, 360): a number or a point
/// of the 16-wind rose ("N", "NE", "SSW", ...).
std::optional<float> parseDirection(std::string_view value);

/// A light's colour temperature in kelvin from `light:colour`: "3000", "3000 K", or a
/// name ("white", "warm_white", "orange", "yellow", ...).
std::optional<float> parseColourTemperature(std::string_view value);

/// True for "yes", "true" and "1".
bool isYes(std::string_view value);

/// `roof:shape` value -> RoofShape (Unknown for unlisted values).
RoofShape parseRoofShape(std::string_view value);

/// `building=` value -> BuildingType (Generic for "yes" and unlisted values).
BuildingType parseBuildingType(std::string_view value);

/// `building:material` value -> BuildingMaterial (Unknown for unlisted values).
BuildingMaterial parseMaterial(std::string_view value);

/// `highway=` value -> HighwayClass (Other for unlisted values).
HighwayClass parseHighwayClass(std::string_view value);

/// `sidewalk=` value -> Sidewalk (Unknown for unlisted values).
Sidewalk parseSidewalk(std::string_view value);

/// `surface=` value -> RoadSurface, by look (concrete:plates -> Concrete, compacted -> Gravel,
/// earth -> Dirt, grass_paver -> Grass, ...); the first of a `;` list; Unknown for unlisted values.
RoadSurface parseRoadSurface(std::string_view value);

/// Whether a tag value is malformed rather than merely unlisted: empty, or with characters that
/// no OSM value of a key like `surface` uses (capitals, blanks inside, punctuation but `_ : ; -`).
bool isMalformedValue(std::string_view value);

/// Whether the `;`-separated list `value` holds `name` ("underground;indoor" holds "underground").
bool listHolds(std::string_view value, std::string_view name);

} // namespace urbis
