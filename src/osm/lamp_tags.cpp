#include "osm/lamp_tags.h"

#include "osm/tag_parsing.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace urbis {

namespace {

constexpr int kMaxLights = 16;
constexpr double kMinHeight = 0.5, kMaxHeight = 50.0; // m

/// `value` in lower case with blanks and dashes as underscores, so that "Metal-Halide",
/// "metal halide" and "metal_halide" read alike.
std::string normalised(const char* value) {
    std::string s(trim(value ? value : ""));
    for (char& c : s) c = (c == '-' || c == ' ') ? '_' : char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

template <typename T, size_t N>
std::optional<T> find(const std::array<std::pair<std::string_view, T>, N>& table, std::string_view key) {
    for (const auto& [name, value] : table)
        if (name == key) return value;
    return std::nullopt;
}

/// `lamp_mount` and `support` values alike (the wiki's lists overlap).
constexpr std::array<std::pair<std::string_view, LampMount>, 9> kMounts = {{
    {"straight_mast", LampMount::Pole}, {"cast_steel", LampMount::Pole}, {"pole", LampMount::Pole},
    {"bent_mast", LampMount::BentMast}, {"wall", LampMount::Wall}, {"wall_mounted", LampMount::Wall},
    {"suspended", LampMount::Suspended}, {"wire", LampMount::Suspended}, {"ground", LampMount::Ground}}};

/// `lamp_type` and `light:shape` values that name a head's shape.
constexpr std::array<std::pair<std::string_view, LampHead>, 13> kHeads = {{
    {"lantern", LampHead::Lantern}, {"gaslight", LampHead::Lantern},
    {"globe", LampHead::Globe}, {"sphere", LampHead::Globe}, {"ball", LampHead::Globe},
    {"cone", LampHead::Cone}, {"conical", LampHead::Cone}, {"pendant", LampHead::Cone},
    {"flat", LampHead::Flat}, {"floodlight", LampHead::Flat}, {"panel", LampHead::Flat},
    {"cobra", LampHead::Cobra}, {"cobra_head", LampHead::Cobra}}};

/// Colour temperature (K) by `light:method` (or a `lamp_type` naming one).
constexpr std::array<std::pair<std::string_view, float>, 16> kMethodKelvin = {{
    {"high_pressure_sodium", 2000.0f}, {"sodium", 2000.0f}, {"sodium_vapour", 2000.0f},
    {"sodium_vapor", 2000.0f}, {"low_pressure_sodium", 1800.0f}, {"mercury", 4000.0f},
    {"mercury_vapour", 4000.0f}, {"metal_halide", 3200.0f}, {"led", 4000.0f},
    {"fluorescent", 4000.0f}, {"compact_fluorescent", 4000.0f}, {"gas", 2700.0f},
    {"gaslight", 2700.0f}, {"gas_lantern", 2700.0f}, {"incandescent", 2700.0f}, {"halogen", 2700.0f}}};

float heightOf(LampMount mount) {
    switch (mount) {
    case LampMount::Wall: return 4.5f;
    case LampMount::Suspended: return 7.0f;
    case LampMount::Ground: return 1.0f;
    default: return 6.0f;
    }
}

LampHead defaultHead(LampMount mount, std::string_view mountTag, bool gas) {
    if (mountTag == "cast_steel" || gas) return LampHead::Lantern;
    if (mount == LampMount::Suspended) return LampHead::Cone;
    if (mount == LampMount::Ground) return LampHead::Flat;
    return LampHead::Cobra;
}

} // namespace

Lamp lampFromTags(const TagLookup& tag, int64_t osmId) {
    Lamp lamp;
    lamp.osmId = osmId;
    const std::string mountTag = normalised(tag("lamp_mount"));
    lamp.mount = find(kMounts, mountTag).value_or(find(kMounts, normalised(tag("support"))).value_or(LampMount::Pole));
    lamp.height = heightOf(lamp.mount);
    if (const char* height = tag("height"))
        if (const std::optional<double> h = parseLength(height); h && *h > kMinHeight && *h < kMaxHeight)
            lamp.height = float(*h);

    const char* type = tag("lamp_type");
    const char* method = tag("light:method");
    lamp.lampType = type ? type : method ? method : "";
    const std::string typeName = normalised(type), methodName = normalised(method);
    lamp.colourTemperature = find(kMethodKelvin, methodName).value_or(find(kMethodKelvin, typeName).value_or(0.0f));
    const bool gas = methodName.starts_with("gas") || typeName.starts_with("gas");
    lamp.head = find(kHeads, typeName)
                    .value_or(find(kHeads, normalised(tag("light:shape"))).value_or(defaultHead(lamp.mount, mountTag, gas)));
    if (const char* colour = tag("light:colour"))
        if (const std::optional<float> k = parseColourTemperature(colour)) lamp.colourTemperature = *k;

    if (const char* count = tag("light:count"))
        if (const std::optional<int> n = parseInteger(count); n && *n >= 1 && *n <= kMaxLights) lamp.lightCount = *n;
    if (const char* direction = tag("light:direction"))
        if (const std::optional<float> d = parseDirection(direction)) lamp.direction = *d;
    return lamp;
}

} // namespace urbis
