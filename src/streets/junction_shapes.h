// Where the fitted roads meet (the street graph: a node is a point where roads end; fitRoads split
// them there): each road end's trim and corners, the junction polygons and the sidewalks' corners.
// osm2streets' method: sort a node's roads by angle, cross each road's left edge with the next one's
// right edge (the carriageway's, and the sidewalks' outer edges), trim each road back to the farthest
// crossing and fill the polygon of the trimmed ends' corners and those crossings (host).
#pragma once

#include "model/city_model.h"

#include <cstdint>
#include <vector>

namespace urbis {

/// How one end of a fitted road meets its node, in the road's own frame (left = left of the direction
/// its centerline runs).
struct RoadEnd {
    double trim = 0;                 ///< m of the centerline cut off at this end
    Vec2d left, right;               ///< the carriageway's corners where it ends
    Vec2d leftOuter, rightOuter;     ///< the sidewalks' outer corners there (the carriageway's where none)
    bool leftGoesOn = false;         ///< the left sidewalk continues past this end (a corner, the next road)
    bool rightGoesOn = false;
    bool deadEnd = false;            ///< nothing joins here: the carriageway ends with a face
    bool atJunction = false;         ///< meets a junction polygon of >= 3 carriageways (a stop line)
};

/// A junction polygon: a fan around `centre` over `ring` (counter-clockwise seen from above).
struct JunctionShape {
    Vec2d centre;
    std::vector<Vec2d> ring;
    float elevation = 0;                       ///< m above the ground (a bridge's node)
    uint32_t road = 0;                         ///< the widest road there: its surface, its object
    bool path = false;                         ///< footways meeting (drawn as a path)
    std::vector<std::vector<Vec2d>> bareSides; ///< borders between roads with no sidewalk corner
};

/// A sidewalk's corner round a junction: the strip between the curb line `inner` and `outer`.
struct SidewalkCorner {
    std::vector<Vec2d> inner, outer;           ///< from one road's sidewalk end to the next one's
    float elevation = 0;
    uint32_t road = 0;                         ///< the road whose left sidewalk it continues
};

struct StreetJunctions {
    std::vector<RoadEnd> starts, ends;         ///< per fitted road, at its first and last point
    std::vector<bool> consumed;                ///< per road: nothing left between its trims (not drawn)
    std::vector<JunctionShape> junctions;
    std::vector<SidewalkCorner> corners;
};

/// The ends, junctions and sidewalk corners of the fitted roads (fitRoads), `elevations` per road and
/// centerline vertex (roadElevations; a missing one counts as 0). Carriageways meet only carriageways;
/// paths meet only paths and are cut back at a carriageway's corridor where they touch one.
/// Deterministic, linear in the roads.
StreetJunctions shapeJunctions(const std::vector<Road>& roads, const std::vector<std::vector<float>>& elevations);

/// The point `distance` m along `line` (clamped to it) and the unit direction of the line there.
Vec2d pointAlong(const std::vector<Vec2d>& line, double distance, Vec2d& direction);

} // namespace urbis
