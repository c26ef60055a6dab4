#include "osm/osm_import.h"

#include "osm/geo_projection.h"

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
    for (const Railway& r : city.railways) std::for_each(r.centerline.begin(), r.centerline.end(), add);
    for (const Crossing& c : city.crossings) add(c.position);
    for (const Area& a : city.areas) std::for_each(a.polygon.outer.begin(), a.polygon.outer.end(), add);
    for (const Lamp& l : city.lamps) add(l.position);
    for (const Tree& t : city.trees) add(t.position);
    if (e[0] > e[2]) e = {0, 0, 0, 0};
    return e;
}

nlohmann::json boxJson(const LonLatBox& box) {
    if (!box.valid) return nullptr;
    return {{"min_lon", box.minLon}, {"min_lat", box.minLat}, {"max_lon", box.maxLon}, {"max_lat", box.maxLat}};
}

/// The lon/lat box of the local extent `e` ({minX, minY, maxX, maxY}) through the inverse projection.
LonLatBox lonLatOf(const std::array<double, 4>& e, const GeoOrigin& origin) {
    const GeoProjection projection({origin.lon, origin.lat});
    LonLatBox box{true, HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (Vec2d corner : {Vec2d{e[0], e[1]}, Vec2d{e[2], e[1]}, Vec2d{e[0], e[3]}, Vec2d{e[2], e[3]}}) {
        const LonLat p = projection.unproject(corner);
        box = {true, std::min(box.minLon, p.lon), std::min(box.minLat, p.lat), std::max(box.maxLon, p.lon),
               std::max(box.maxLat, p.lat)};
    }
    return box;
}

/// Inspect's name of each area kind, in AreaKind's order.
constexpr std::array<const char*, 15> kAreaKindNames = {
    "park", "grass", "forest", "water", "residential", "commercial", "industrial", "pitch", "playground",
    "sand", "scrub", "parking", "pedestrian", "cemetery", "farmland"};
static_assert(kAreaKindNames.size() == size_t(AreaKind::Farmland) + 1, "a name for every AreaKind");

/// {reason: count} of `log`, and with `ids` {reason: ["w123", ...]} into `idsOut`.
nlohmann::json countsOf(const ReasonLog& log, bool ids, nlohmann::json& idsOut) {
    nlohmann::json counts = nlohmann::json::object();
    idsOut = nlohmann::json::object();
    for (const auto& [reason, entry] : log) {
        counts[reason] = entry.count;
        if (!ids) continue;
        nlohmann::json& list = idsOut[reason] = nlohmann::json::array();
        for (OsmRef ref : entry.ids) list.push_back(osmRefName(ref));
    }
    return counts;
}

} // namespace

nlohmann::json inspectJson(const CityModel& city, bool ids) {
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
    j["crossings"] = city.crossings.size();
    j["railways"] = city.railways.size();
    nlohmann::json areas = nlohmann::json::object();
    for (size_t k = 0; k < kAreaKindNames.size(); ++k) areas[kAreaKindNames[k]] = countAreas(AreaKind(k));
    j["areas"] = areas;
    j["heights"] = {{"from_height_tag", countHeights(HeightSource::HeightTag)},
                    {"from_levels", countHeights(HeightSource::Levels)},
                    {"from_nearby_median", countHeights(HeightSource::NearbyMedian)},
                    {"from_type_table", countHeights(HeightSource::TypeTable)},
                    {"from_range", countHeights(HeightSource::Range)}};
    nlohmann::json droppedIds, repairedIds;
    j["dropped"] = countsOf(city.dropped, ids, droppedIds);
    j["repaired"] = countsOf(city.repaired, ids, repairedIds);
    if (ids) {
        j["dropped_ids"] = droppedIds;
        j["repaired_ids"] = repairedIds;
    }
    j["extent_m"] = {{"width", e[2] - e[0]}, {"depth", e[3] - e[1]}};
    j["origin"] = {{"lat", city.origin.lat}, {"lon", city.origin.lon}};
    j["bounds"] = {{"kept", boxJson(lonLatOf(e, city.origin))}, {"header", boxJson(city.headerBox)},
                   {"crop", boxJson(city.cropBox)}, {"crop_source", city.cropBoxSource}};
    return j;
}

} // namespace urbis
