#include "osm/tag_parsing.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <string>
#include <utility>

namespace urbis {

namespace {

constexpr double kMaxLength = 1000.0; // m; no structure is taller
constexpr double kFoot = 0.3048, kInch = 0.0254;

/// Reads the leading decimal number of `s` ("12", "12.5", "12,5", "-5", "1e30") and moves
/// `s` past it and past the blanks that follow.
std::optional<double> takeNumber(std::string_view& s) {
    size_t n = 0;
    while (n < s.size() && std::string_view("0123456789.,-eE").find(s[n]) != std::string_view::npos) ++n;
    std::string text(s.substr(0, n));
    std::replace(text.begin(), text.end(), ',', '.');
    double v = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (n == 0 || ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
    s = trim(s.substr(n));
    return v;
}

template <typename T, size_t N>
T lookup(const std::array<std::pair<std::string_view, T>, N>& table, std::string_view key, T fallback) {
    for (const auto& [name, value] : table)
        if (name == key) return value;
    return fallback;
}

} // namespace

std::string_view trim(std::string_view s) {
    const auto isSpace = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
    while (!s.empty() && isSpace(s.front())) s.remove_prefix(1);
    while (!s.empty() && isSpace(s.back())) s.remove_suffix(1);
    return s;
}

bool oneOf(std::string_view s, std::initializer_list<std::string_view> names) {
    return std::find(names.begin(), names.end(), s) != names.end();
}

std::optional<double> parseLength(std::string_view value) {
    std::string_view s = trim(value);
    const std::optional<double> number = takeNumber(s);
    if (!number) return std::nullopt;
    double metres = 0;
    if (oneOf(s, {"", "m", "meter", "meters", "metre", "metres"})) {
        metres = *number;
    } else if (oneOf(s, {"ft", "feet", "foot"})) {
        metres = *number * kFoot;
    } else if (oneOf(s, {"\"", "in", "inch", "inches"})) {
        metres = *number * kInch;
    } else if (s.front() == '\'') { // feet, maybe followed by inches: 40'6"
        s = trim(s.substr(1));
        double inches = 0;
        if (!s.empty()) {
            const std::optional<double> in = takeNumber(s);
            if (!in || !oneOf(s, {"\"", "''", "in"})) return std::nullopt;
            inches = *in;
        }
        metres = *number * kFoot + inches * kInch;
    } else {
        return std::nullopt;
    }
    if (!std::isfinite(metres) || metres < 0.0 || metres > kMaxLength) return std::nullopt;
    return metres;
}

std::optional<double> parseElevation(std::string_view value) {
    std::string_view s = trim(value);
    const std::optional<double> number = takeNumber(s);
    if (!number) return std::nullopt;
    double metres = *number;
    if (oneOf(s, {"ft", "feet"})) metres *= kFoot;
    else if (!oneOf(s, {"", "m"})) return std::nullopt;
    if (!(metres >= -500.0 && metres <= 9000.0)) return std::nullopt;
    return metres;
}

std::optional<double> parseLevels(std::string_view value) {
    std::string_view s = trim(value);
    const std::optional<double> number = takeNumber(s);
    if (!number || !s.empty() || !std::isfinite(*number) || *number < 0.0 || *number > 300.0)
        return std::nullopt;
    return number;
}

std::optional<float> parseAngle(std::string_view value) {
    std::string_view s = trim(value);
    const std::optional<double> degrees = takeNumber(s);
    if (!degrees || !oneOf(trim(s), {"", "°", "deg"}) || !(*degrees > 0.0 && *degrees < 90.0)) return std::nullopt;
    return float(*degrees);
}

std::optional<int> parseInteger(std::string_view value) {
    const std::string_view s = trim(value);
    int v = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (s.empty() || ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
    return v;
}

std::optional<float> parseDirection(std::string_view value) {
    static constexpr std::array<std::string_view, 16> kRose = {
        "N", "NNE", "NE", "ENE", "E", "ESE", "SE", "SSE",
        "S", "SSW", "SW", "WSW", "W", "WNW", "NW", "NNW"};
    std::string_view s = trim(value);
    for (size_t i = 0; i < kRose.size(); ++i)
        if (s == kRose[i]) return float(i) * 22.5f;
    const std::optional<double> degrees = takeNumber(s);
    if (!degrees || !s.empty() || !std::isfinite(*degrees)) return std::nullopt;
    const double wrapped = std::fmod(std::fmod(*degrees, 360.0) + 360.0, 360.0);
    return float(wrapped);
}

std::optional<float> parseColourTemperature(std::string_view value) {
    static constexpr std::array<std::pair<std::string_view, float>, 7> kNamed = {{
        {"orange", 2000.0f}, {"yellow", 2700.0f}, {"warm_white", 3000.0f}, {"white", 4000.0f},
        {"neutral_white", 4000.0f}, {"cool_white", 5500.0f}, {"cold_white", 6000.0f}}};
    std::string_view s = trim(value);
    if (const float named = lookup(kNamed, s, 0.0f); named > 0.0f) return named;
    const std::optional<double> kelvin = takeNumber(s);
    if (!kelvin || !oneOf(s, {"", "K", "k"}) || *kelvin < 1000.0 || *kelvin > 20000.0)
        return std::nullopt;
    return float(*kelvin);
}

bool isYes(std::string_view value) { return oneOf(value, {"yes", "true", "1"}); }

RoofShape parseRoofShape(std::string_view value) {
    static constexpr std::array<std::pair<std::string_view, RoofShape>, 15> kTable = {{
        {"flat", RoofShape::Flat}, {"skillion", RoofShape::Skillion},
        {"gabled", RoofShape::Gabled}, {"saltbox", RoofShape::Gabled},
        {"cross_gabled", RoofShape::Gabled}, {"hipped", RoofShape::Hipped},
        {"half-hipped", RoofShape::Hipped}, {"side_hipped", RoofShape::Hipped},
        {"pyramidal", RoofShape::Pyramidal}, {"dome", RoofShape::Dome},
        {"onion", RoofShape::Onion}, {"gambrel", RoofShape::Gambrel},
        {"mansard", RoofShape::Mansard}, {"round", RoofShape::Round},
        {"sawtooth", RoofShape::Skillion}}};
    return lookup(kTable, trim(value), RoofShape::Unknown);
}

BuildingType parseBuildingType(std::string_view value) {
    using T = BuildingType;
    static constexpr std::array<std::pair<std::string_view, T>, 50> kTable = {{
        {"residential", T::Residential}, {"terrace", T::Residential},
        {"house", T::House}, {"detached", T::House}, {"semidetached_house", T::House},
        {"bungalow", T::House}, {"farm", T::House}, {"cabin", T::House}, {"static_caravan", T::House},
        {"apartments", T::Apartments}, {"dormitory", T::Apartments},
        {"commercial", T::Commercial}, {"retail", T::Retail}, {"supermarket", T::Retail},
        {"kiosk", T::Retail}, {"office", T::Office},
        {"industrial", T::Industrial}, {"manufacture", T::Industrial}, {"factory", T::Industrial},
        {"warehouse", T::Warehouse}, {"storage_tank", T::Industrial}, {"barn", T::Warehouse},
        {"farm_auxiliary", T::Warehouse},
        {"church", T::Religious}, {"cathedral", T::Religious}, {"chapel", T::Religious},
        {"mosque", T::Religious}, {"temple", T::Religious}, {"synagogue", T::Religious},
        {"shrine", T::Religious}, {"religious", T::Religious}, {"monastery", T::Religious},
        {"civic", T::Civic}, {"public", T::Civic}, {"government", T::Civic},
        {"townhall", T::Civic}, {"fire_station", T::Civic}, {"train_station", T::Civic},
        {"transportation", T::Civic}, {"museum", T::Civic},
        {"school", T::School}, {"university", T::School}, {"college", T::School},
        {"kindergarten", T::School}, {"hospital", T::Hospital}, {"hotel", T::Hotel},
        {"garage", T::Garage}, {"garages", T::Garage}, {"shed", T::Shed}, {"roof", T::Roof}}};
    return lookup(kTable, trim(value), T::Generic);
}

BuildingMaterial parseMaterial(std::string_view value) {
    using M = BuildingMaterial;
    static constexpr std::array<std::pair<std::string_view, M>, 13> kTable = {{
        {"brick", M::Brick}, {"concrete", M::Concrete}, {"reinforced_concrete", M::Concrete},
        {"glass", M::Glass}, {"metal", M::Metal}, {"steel", M::Metal}, {"plaster", M::Plaster},
        {"stucco", M::Plaster}, {"stone", M::Stone}, {"wood", M::Wood},
        {"sandstone", M::Sandstone}, {"timber_framing", M::Timber}, {"timber", M::Timber}}};
    return lookup(kTable, trim(value), M::Unknown);
}

HighwayClass parseHighwayClass(std::string_view value) {
    using H = HighwayClass;
    static constexpr std::array<std::pair<std::string_view, H>, 24> kTable = {{
        {"motorway", H::Motorway}, {"motorway_link", H::Motorway}, {"trunk", H::Trunk},
        {"trunk_link", H::Trunk}, {"primary", H::Primary}, {"primary_link", H::Primary},
        {"secondary", H::Secondary}, {"secondary_link", H::Secondary},
        {"tertiary", H::Tertiary}, {"tertiary_link", H::Tertiary},
        {"unclassified", H::Unclassified}, {"road", H::Unclassified},
        {"residential", H::Residential}, {"service", H::Service},
        {"living_street", H::LivingStreet}, {"pedestrian", H::Pedestrian},
        {"footway", H::Footway}, {"sidewalk", H::Footway}, {"corridor", H::Footway},
        {"cycleway", H::Cycleway}, {"path", H::Path}, {"bridleway", H::Path},
        {"steps", H::Steps}, {"track", H::Track}}};
    return lookup(kTable, trim(value), H::Other);
}

Sidewalk parseSidewalk(std::string_view value) {
    using S = Sidewalk;
    static constexpr std::array<std::pair<std::string_view, S>, 7> kTable = {{
        {"both", S::Both}, {"left", S::Left}, {"right", S::Right}, {"no", S::None},
        {"none", S::None}, {"separate", S::Separate}, {"yes", S::Both}}};
    return lookup(kTable, trim(value), S::Unknown);
}

RoadSurface parseRoadSurface(std::string_view value) {
    using R = RoadSurface;
    static constexpr std::array<std::pair<std::string_view, R>, 30> kTable = {{
        {"asphalt", R::Asphalt}, {"paved", R::Asphalt}, {"chipseal", R::Asphalt},
        {"concrete", R::Concrete}, {"concrete:plates", R::Concrete}, {"concrete:lanes", R::Concrete},
        {"paving_stones", R::PavingStones}, {"paving_stones:lanes", R::PavingStones},
        {"bricks", R::PavingStones}, {"sett", R::Sett}, {"unhewn_cobblestone", R::Cobblestone},
        {"cobblestone", R::Cobblestone}, {"cobblestone:flattened", R::Sett}, {"gravel", R::Gravel},
        {"fine_gravel", R::Gravel}, {"compacted", R::Gravel}, {"pebblestone", R::Gravel},
        {"unpaved", R::Gravel}, {"dirt", R::Dirt}, {"ground", R::Dirt}, {"earth", R::Dirt},
        {"mud", R::Dirt}, {"sand", R::Dirt}, {"grass", R::Grass}, {"grass_paver", R::Grass},
        {"wood", R::Wood}, {"woodchips", R::Dirt}, {"metal", R::Metal}, {"metal_grid", R::Metal},
        {"steel", R::Metal}}};
    const std::string_view s = trim(value);
    return lookup(kTable, trim(s.substr(0, s.find(';'))), R::Unknown);
}

bool isMalformedValue(std::string_view value) {
    const std::string_view s = trim(value);
    const auto allowed = [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == ':' || c == ';' || c == '-';
    };
    return s.empty() || !std::all_of(s.begin(), s.end(), allowed);
}

bool listHolds(std::string_view value, std::string_view name) {
    while (true) {
        const size_t end = value.find(';');
        if (trim(value.substr(0, end)) == name) return true;
        if (end == std::string_view::npos) return false;
        value.remove_prefix(end + 1);
    }
}

} // namespace urbis
