// CityModel -> scene geometry: every building's walls (procedural wall records, or their triangle
// twin) and roof, and the ground's material.
#pragma once

#include "scene/geometry_modes.h"
#include "scene/triangle_mesh.h"
#include "scene/wall_record.h"
#include "math/bounds.h"
#include "model/city_model.h"
#include "scene/geometry_modes.h"
#include "scene/material.h"
#include "scene/lamp_record.h"
#include "scene/road_segment.h"
#include "nature/tree_options.h"
#include "scene/forest_record.h"
#include "scene/tree_record.h"
#include "streets/bridge_spans.h"
#include "streets/traffic_side.h"
#include "streets/water_options.h"

#include <map>
#include <optional>
#include <string>

namespace urbis {

/// The city's materials that follow no building's colour (a scene description may change them).
struct CityMaterials {
    Vec3f groundAlbedo{0.10f, 0.11f, 0.09f};
    Vec3f glassTransmittance{0.85f, 0.9f, 0.9f};   ///< the windows' panes (FacadeMaterial::Glass)
    float glassIor = 1.5f;
    /// Lit rooms behind windows: its luminance is a lit room's mean (0.0044, some 140 cd/m^2 in the units
    /// of lights/lamp_light.h), each window's colour temperature and intensity its own (lights/window_light.h).
    Vec3f litRoomEmission{0.0067f, 0.0040f, 0.0019f};
};

struct CityMeshOptions {
    GeometryModes geometry;   ///< walls=plain: each building a closed mass model (every edge shared)
    CityMaterials materials;
    bool streets = true;      ///< roads, sidewalks, ground cover, lamps (streets/); false: buildings on the bare ground
    float hour = 12.0f;       ///< local clock hours: which rooms are lit (citygen/window_schedule.h)
    /// The side traffic keeps (lanes, stop lines); nullopt: by the city's place (trafficSideOf).
    std::optional<TrafficSide> traffic;
    /// Bytes the triangle twin may take to build; 0: the memory available now.
    size_t memoryLimit = 0;
    WaterOptions water;       ///< the water's bed and waves (streets/water_depth.h)
    TreeOptions trees;        ///< placed with the streets (none with streets = false)
    /// The twin's lit rooms each with its window's colour and intensity (citygen/lit_room_palette.h),
    /// as the procedural walls show them; else all of FacadeMaterial::RoomLit. For exports.
    bool litRoomLooks = false;
};

struct CityMesh {
    TriangleMesh mesh;
    std::vector<WallRecord> walls;             ///< procedural walls (empty with walls=triangles)
    std::vector<RoadSegment> roadSegments;     ///< the carriageways' markings (streets/street_mesh.h)
    std::vector<LampRecord> lamps;             ///< procedural street lamps (empty with lamps=triangles)
    std::vector<BridgeSpan> bridgeSpans;       ///< bridges' decks (streets/bridge_spans.h), for a terrain
    std::map<uint32_t, float> waterElevations; ///< OSM `ele` of water bodies by object id: their level on a terrain
    std::map<uint32_t, std::vector<Vec2d>> waterFlows;  ///< rivers drawn from lines: their flow (world x, z) by object id
    std::vector<Material> materials;
    uint32_t groundMaterial = 0;               ///< the ground plane's entry in materials
    Bounds3f cityBounds;                       ///< world bounds of the buildings (ground and streets excluded)
    std::vector<Bounds3f> framingPieces;       ///< bounds of the buildings in columns of a grid over cityBounds: its shape, for frameCity
    std::map<std::string, size_t> trianglesByKind;
    std::map<std::string, uint64_t> streetCounts;  ///< street objects made, by kind (StreetMesh::counts)
    size_t facadeWalls = 0;                    ///< walls with a facade, in either representation
    size_t facadeCells = 0;                    ///< their floors x slots
    /// Buildings that could not be meshed, by reason: meshBuilding's, or "mesh_failed" where meshing threw.
    std::map<std::string, uint64_t> dropped;
    uint64_t holesDropped = 0;                 ///< footprint holes the cleaning dropped (citygen/footprint_cleaning.h)
    std::map<std::string, uint64_t> roofFallbacks;  ///< roofs meshed as a simpler shape (unknown shape -> flat, ...), by reason
    std::vector<TreeRecord> trees;             ///< sphere-traced trees (empty with trees=triangles)
    std::vector<ForestRecord> forests;         ///< the forest beyond the city (trees.outer_forest), procedural in any mode
};

/// Meshes the whole city (object id of building i is i + 1; 0 is the ground) in parallel; the
/// result does not depend on the thread count. No building's input or failure ends the city: a
/// building that cannot be meshed is left out and counted in `dropped`. With walls=triangles the facades' triangle twin
/// is estimated first and InputError thrown, before building it, if it would not fit in memory.
CityMesh meshCity(const CityModel& city, const CityMeshOptions& options = {});

} // namespace urbis
