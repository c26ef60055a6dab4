// CityModel -> the streets' scene geometry: carriageways with their markings' records, junctions,
// sidewalks and curbs, bridges, railways, ground cover and water (stored triangles), and street lamps
// (analytic records, or their triangle twin).
#pragma once

#include "model/city_model.h"
#include "scene/geometry_modes.h"
#include "scene/lamp_record.h"
#include "scene/road_segment.h"
#include "scene/triangle_mesh.h"
#include "streets/bridge_spans.h"
#include "streets/water_options.h"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace urbis {

struct StreetOptions {
    Representation lamps = Representation::Procedural;
    uint32_t firstMaterial = 0;   ///< index of StreetMaterial 0 in the scene's materials
    uint32_t firstObject = 1;     ///< object id of the first street object (ids after the buildings')
    bool americanMarkings = false;///< yellow centre lines (the Americas); white elsewhere
    bool leftHandTraffic = false; ///< traffic keeps left (streets/traffic_side.h): lanes and stop lines mirrored
    WaterOptions water;           ///< the water's bed and waves (streets/water_depth.h)
};

struct StreetMesh {
    TriangleMesh mesh;                          ///< every stored street triangle
    std::vector<RoadSegment> roadSegments;      ///< a Road triangle's TriangleInfo::object indexes these
    std::vector<LampRecord> lamps;              ///< analytic street lamps (StreetOptions::lamps == Procedural)
    std::vector<BridgeSpan> bridgeSpans;        ///< road and railway bridges' decks, for a terrain
    std::map<uint32_t, float> waterElevations;  ///< OSM `ele` (Area::ele) of water bodies, by object id
    std::map<uint32_t, std::vector<Vec2d>> waterFlows;  ///< rivers drawn from lines: Area::flowLine in world (x, z), by object id
    /// What was made, keyed roads, junctions, sidewalks, crossings, ground_cover, water, bridges,
    /// railways, lamps (for --stats `counts`).
    std::map<std::string, uint64_t> counts;
    /// Stored triangles by kind, same keys (for --stats `triangles_by_kind`).
    std::map<std::string, size_t> trianglesByKind;
    /// Objects left out, by reason (a road inside a building, a degenerate area, ...).
    std::map<std::string, uint64_t> dropped;
    uint32_t objects = 0;                       ///< object ids used: [firstObject, firstObject + objects)
};

} // namespace urbis
