// What the OSM reader collects: attributes already read from tags, geometry still in
// degrees, because the crop box and projection are known only after the whole file.
#pragma once

#include "model/city_model.h"
#include "osm/crop.h"
#include "osm/geo_projection.h"

#include <cmath>
#include <map>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

namespace urbis {

using GeoLine = std::vector<LonLat>;

/// What a closed way or multipolygon stands for.
enum class PolygonRole : uint8_t { None, Building, Part, Area };

/// The key under which a drop `reason` is counted for a role: building outlines use the
/// bare reason ("outside_bbox"), the others a prefix ("part_outside_bbox", "area_...").
inline std::string dropKey(PolygonRole role, const char* reason) {
    switch (role) {
    case PolygonRole::Part: return std::string("part_") + reason;
    case PolygonRole::Area: return std::string("area_") + reason;
    default: return reason;
    }
}

/// An outer ring with its holes, in degrees; rings need not be closed or oriented.
struct GeoPolygon {
    GeoLine outer;
    std::vector<GeoLine> holes;
};

/// A building or building:part: attributes from tags, its polygons (a multipolygon
/// relation may have several outer rings), or why it has none usable.
struct RawBuilding {
    Building attributes;
    std::vector<GeoPolygon> polygons;
    const char* problem = nullptr; ///< a drop reason ("incomplete_geometry", ...) or nullptr
    std::map<std::string, uint64_t> tagIssues; ///< counted (as repaired) only if the building is kept
    bool underground = false;      ///< isUnderground: dropped as "underground" where it would be kept
};

/// A ground-cover area (park, water, square, car park, landuse...); like RawBuilding.
struct RawArea {
    Area attributes;
    std::vector<GeoPolygon> polygons;
    const char* problem = nullptr;
    std::map<std::string, uint64_t> tagIssues; ///< counted (as repaired) only if the area is kept
};

/// A highway or railway way: attributes and its centerline pieces (split where nodes are missing).
template <typename Way>
struct RawLine {
    Way attributes;
    std::vector<GeoLine> pieces;
    std::map<std::string, uint64_t> tagIssues; ///< counted (as repaired) only if the way is kept
};
using RawRoad = RawLine<Road>;
using RawRailway = RawLine<Railway>;

/// A natural=coastline way: its pieces (split where nodes are missing), in its OSM direction.
struct RawCoastline {
    int64_t osmId = 0;
    std::vector<GeoLine> pieces;
};

/// A river mapped as a line (waterwayWidthFromTags): its pieces in its OSM direction, and its width.
struct RawWaterway {
    int64_t osmId = 0;
    float width = 0;   ///< m
    std::vector<GeoLine> pieces;
};

/// A crossing at a node, still in degrees.
struct RawCrossing {
    Crossing attributes;  ///< osmId: the node's id
    LonLat position;
};

struct RawFeatures {
    std::vector<RawBuilding> buildings;
    std::vector<RawArea> areas;
    std::vector<RawRoad> roads;
    std::vector<RawRailway> railways;
    std::vector<RawCrossing> crossings;        ///< crossing nodes (highway/railway/footway=crossing)
    std::vector<RawCoastline> coastlines;      ///< natural=coastline ways (osm/coastline.h)
    std::vector<RawWaterway> waterways;        ///< rivers mapped as lines
    /// Nodes of footway=crossing ways, each with the way's kind: a crossing where a carriageway
    /// shares the node (and no crossing node stands there already).
    std::vector<RawCrossing> crossingWayNodes;
    std::unordered_set<int64_t> carriagewayNodes; ///< ids of the nodes of carriageway roads (isCarriageway)
    std::vector<std::pair<Lamp, LonLat>> lamps;
    std::vector<std::pair<Tree, LonLat>> trees;
    GeoBox headerBox;                             ///< invalid when the file has none
    GeoBox dataExtent{HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL}; ///< of all node locations
    ReasonLog dropped;                            ///< objects dropped while reading (incomplete relations)
};

} // namespace urbis
