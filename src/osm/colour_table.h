// Colours of buildings: OSM colour values and material colours (untagged buildings take
// theirs from building_palette.h).
// Tables hold sRGB; everything returned is linear (DESIGN.md: colours are linear).
#pragma once

#include "model/city_model.h"

#include <cstdint>
#include <optional>
#include <string_view>

namespace urbis {

/// Linear value of one sRGB-encoded channel in [0,1] (IEC 61966-2-1 transfer curve).
float linearFromSrgb(float encoded);

/// Linear colour of a packed sRGB 0xRRGGBB value.
Rgb fromSrgbHex(uint32_t rgb);

/// Linear colour of a `building:colour` / `roof:colour` value: a name ("red", "white",
/// "grey", "light_brown", ...: CSS names, case, blanks, '_' and '-' ignored) or "#rgb" /
/// "#rrggbb". nullopt when unparsable.
std::optional<Rgb> parseColour(std::string_view value);

/// Typical wall colour (linear) of a facade material; nullopt for Unknown.
std::optional<Rgb> materialColour(BuildingMaterial material);

/// Typical colour (linear) of a `roof:material` value ("roof_tiles", "slate", "copper",
/// ...); nullopt for unlisted values.
std::optional<Rgb> roofMaterialColour(std::string_view roofMaterial);

} // namespace urbis
