#include "osm/osm_import.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace urbis {

namespace {

/// Bounds of every point of the model's geometry: {minX, minY, maxX, maxY}, metres.
std::array<double, 4> extentOf(const CityModel& city) {
    std::array<double, 4> e{HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    const auto add = [&e](Vec2d p) {
        e = {std::min(e[0], p.x), std::min(e[1], p.y), std::max(e[2], p.x), std::max(e[3], p.y)};
    };
    for (const Building& b : city.buildings) std::for_each(b.footprint.outer.begin(), b.footprint.outer.end(), add);
    for (const Road& r : city.roads) std::for_each(r.centerline.begin(), r.centerline.end(), add);
    for (const Area& a : city.areas) std::for_each(a.polygon.outer.begin(), a.polygon.outer.end(), add);
    for (const Lamp& l : city.lamps) add(l.position);
    for (const Tree& t : city.trees) add(t.position);
    if (e[0] > e[2]) e = {0, 0, 0, 0};
    return e;
}

} // namespace

nlohmann::json inspectJson(const CityModel& city) {
    const auto countAreas = [&city](AreaKind kind) {
        return std::count_if(city.areas.begin(), city.areas.end(), [kind](const Area& a) { return a.kind == kind; });
    };
    const auto countHeights = [&city](HeightSource source) {
        return std::count_if(city.buildings.begin(), city.buildings.end(),
                             [source](const Building& b) { return b.heightSource == source; });
    };
    const std::array<double, 4> e = extentOf(city);
    nlohmann::json j;
    j["source"] = city.source;
    j["buildings"] = city.buildings.size();
    j["building_parts"] = city.buildingParts();
    j["roads"] = city.roads.size();
    j["lamps"] = city.lamps.size();
    j["trees"] = city.trees.size();
    j["parks"] = countAreas(AreaKind::Park);
    j["grass"] = countAreas(AreaKind::Grass);
    j["forests"] = countAreas(AreaKind::Forest);
    j["water"] = countAreas(AreaKind::Water);
    j["heights"] = {{"from_height_tag", countHeights(HeightSource::HeightTag)},
                    {"from_levels", countHeights(HeightSource::Levels)},
                    {"from_nearby_median", countHeights(HeightSource::NearbyMedian)},
                    {"from_type_table", countHeights(HeightSource::TypeTable)},
                    {"from_range", countHeights(HeightSource::Range)}};
    j["dropped"] = nlohmann::json::object();
    for (const auto& [reason, n] : city.dropped) j["dropped"][reason] = n;
    j["extent_m"] = {{"width", e[2] - e[0]}, {"depth", e[3] - e[1]}};
    j["origin"] = {{"lat", city.origin.lat}, {"lon", city.origin.lon}};
    return j;
}

} // namespace urbis
