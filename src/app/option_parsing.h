// Parsing of the command line's compound values ("20:100", "x,y,z,...").
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace urbis {

/// Splits `text` at `separator` into finite numbers; throws InputError naming `option` if any part
/// is not a number or the count is not in [minCount, maxCount].
std::vector<double> parseNumberList(const std::string& option, const std::string& text, char separator,
                                    size_t minCount, size_t maxCount);

/// "MINLON,MINLAT,MAXLON,MAXLAT" in degrees; nullopt for an empty text. Throws InputError on a box
/// that is malformed, inverted or off the globe.
std::optional<std::array<double, 4>> parseBbox(const std::string& text);

/// "LON,LAT" in degrees (longitude in [-180, 180], latitude in [-90, 90]). Throws a usage
/// InputError naming `option` on anything else.
std::array<double, 2> parseLocation(const std::string& option, const std::string& text);

/// A size in bytes: a number with an optional binary unit K, M, G or T (KiB ... TiB; "KB",
/// "GiB" and lower case too), e.g. "8G", "512M", "2000000000", "1.5G". Throws a usage
/// InputError naming `option` on anything else, on zero and on sizes past 2^63.
size_t parseMemorySize(const std::string& option, const std::string& text);

} // namespace urbis
