// Where a city's trees stand (host): its mapped trees (OSM natural=tree nodes and tree rows, the
// generated city's street and park trees) kept where they may stand, and trees filled into woods,
// forests, parks and scrub by a seeded jittered grid with a density (TreeOptions).
#pragma once

#include "model/cell_grid.h"
#include "model/city_model.h"
#include "nature/tree_options.h"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace urbis {

/// What a tree may not stand on: roads (their carriageways, and for filled trees their sidewalks),
/// buildings and building parts, water and paved or sports areas (pedestrian, parking, pitch,
/// playground). Tunnels and underground roads do not count. Model metres (x east, y north).
class TreeGround {
public:
    explicit TreeGround(const CityModel& city);

    /// Whether a trunk at `p` stands within `clearance` metres of a carriageway (or, with
    /// `sidewalks`, of a road's corridor: its carriageway and kTreeSidewalkAllowance each side, and
    /// of any path).
    bool onRoad(Vec2d p, double clearance, bool sidewalks) const;
    /// Whether `p` lies in a building's footprint (or within `clearance` of its edge).
    bool inBuilding(Vec2d p, double clearance) const;
    /// Whether `p` lies in water (or within `clearance` of it).
    bool inWater(Vec2d p, double clearance) const;
    /// Whether `p` lies in a paved or sports area (or within `clearance` of one).
    bool inPaved(Vec2d p, double clearance) const;

private:
    struct Segment {
        Vec2d a, b;
        double halfWidth;
        bool carriageway;
    };
    bool inPolygons(const std::vector<const Polygon*>& polygons, const CellGrid& grid, Vec2d p, double clearance) const;

    std::vector<Segment> roads_;
    CellGrid roadGrid_;
    std::vector<const Polygon*> buildings_, water_, paved_;
    CellGrid buildingGrid_, waterGrid_, pavedGrid_;
};

/// Metres beside a carriageway that a filled tree keeps clear for its sidewalk.
inline constexpr double kTreeSidewalkAllowance = 3.0;

/// The city's trees: its mapped ones that stand on no carriageway, in no building and in no water
/// (a paved square's trees stand in its pits; the others are counted in `dropped`, by reason tree_on_road, tree_in_building, tree_in_water),
/// then the areas' filled-in trees. Deterministic: a filled tree's place depends on the seed, its
/// area's id and its grid cell only.
std::vector<Tree> placeTrees(const CityModel& city, const TreeOptions& options, std::map<std::string, uint64_t>& dropped);

/// Trees per hectare that `options` fills into an area of `kind` (0: none).
float fillDensity(AreaKind kind, const TreeOptions& options);

} // namespace urbis
