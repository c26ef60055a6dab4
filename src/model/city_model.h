// CityModel: the plain records that the OSM importer and the procedural layout both produce,
// and everything downstream (citygen, inspect) consumes. Host only; no rendering types here.
//
// Coordinates are local metres on a plane tangent to the Earth at `origin`:
// x grows to the east, y to the north. (The renderer maps them to world x = east,
// z = -north, y = up.)
#pragma once

#include "model/reason_log.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace urbis {

struct Vec2d {
    double x = 0, y = 0;
};

/// A closed ring of points; the closing point is not repeated.
/// Outer rings are counter-clockwise, holes clockwise (seen from above, x east, y north).
using Ring = std::vector<Vec2d>;

struct Polygon {
    Ring outer;
    std::vector<Ring> holes;
};

/// Linear sRGB-primaries colour in [0,1].
struct Rgb {
    float r = 0.8f, g = 0.8f, b = 0.8f;
};

enum class RoofShape : uint8_t {
    Flat, Skillion, Gabled, Hipped, Pyramidal, Dome, Onion, Gambrel, Mansard, Round, Unknown
};

/// Broad building classes that drive default colours and (later) facade styles.
enum class BuildingType : uint8_t {
    Generic, Residential, House, Apartments, Commercial, Retail, Office, Industrial, Warehouse,
    Religious, Civic, School, Hospital, Hotel, Garage, Shed, Roof
};

enum class BuildingMaterial : uint8_t {
    Unknown, Brick, Concrete, Glass, Metal, Plaster, Stone, Wood, Sandstone, Timber
};

/// Where a building's height came from, most trusted first: its `height` tag; its
/// `building:levels`; the median of tagged buildings of its type nearby; the table of typical
/// heights by type and region; or the explicit seeded range (`--building-height-range`).
/// The last three are estimates (osm/height_estimate.h).
enum class HeightSource : uint8_t { HeightTag, Levels, NearbyMedian, TypeTable, Range };

/// Whether the height came from the building's own tags rather than an estimate.
inline bool isTagged(HeightSource source) { return source == HeightSource::HeightTag || source == HeightSource::Levels; }

struct Building {
    int64_t osmId = 0;            ///< way id, or relation id (negative) for multipolygons; 0 if generated
    bool isPart = false;          ///< a building:part (its outline building was replaced)
    Polygon footprint;
    float minHeight = 0.0f;       ///< m above ground where the walls start
    float height = 10.0f;         ///< m above ground of the highest point, roof included
    float roofHeight = 0.0f;      ///< m of `height` taken by the roof; 0 on a sloped roof: untagged, the mesher picks it
    float roofAngle = -1.0f;      ///< roof:angle, degrees from horizontal; -1 if untagged
    int levels = -1;              ///< building:levels above ground, -1 if unknown
    int minLevel = 0;
    int roofLevels = 0;
    HeightSource heightSource = HeightSource::TypeTable;
    RoofShape roofShape = RoofShape::Flat;
    float roofDirection = -1.0f;  ///< degrees clockwise from north, -1 if untagged
    bool roofAcross = false;      ///< roof:orientation=across: ridge across the longest side
    BuildingType type = BuildingType::Generic;
    BuildingMaterial material = BuildingMaterial::Unknown;
    Rgb wallColour;
    Rgb roofColour{0.35f, 0.33f, 0.32f};
    bool wallColourTagged = false; ///< wallColour from building:colour or building:material, else a palette's
    bool roofColourTagged = false; ///< roofColour from roof:colour or roof:material, else a palette's
    uint32_t seed = 0;            ///< per-building seed for everything procedural
};

enum class HighwayClass : uint8_t {
    Motorway, Trunk, Primary, Secondary, Tertiary, Unclassified, Residential, Service,
    LivingStreet, Pedestrian, Footway, Cycleway, Path, Steps, Track, Other
};

enum class Sidewalk : uint8_t { Unknown, None, Left, Right, Both, Separate };

/// `surface=*` of a road, a path or a paved area, grouped by how it looks.
enum class RoadSurface : uint8_t {
    Asphalt, Concrete, PavingStones, Sett, Cobblestone, Gravel, Dirt, Grass, Wood, Metal, Unknown
};

/// `footway=*` of a footway: a sidewalk mapped as its own way, a crossing, or neither.
enum class FootwayKind : uint8_t { None, Sidewalk, Crossing };

struct Road {
    int64_t osmId = 0;
    /// Counter-clockwise along the way's direction (oneway=-1 already flipped). Shared OSM nodes are
    /// shared points: equal coordinates, bit for bit, are one node of the street graph.
    std::vector<Vec2d> centerline;
    HighwayClass highway = HighwayClass::Residential;
    float width = 6.0f;           ///< m, carriageway; from `width` or estimated from lanes and class
    int lanes = 2;                ///< all lanes of the carriageway
    int lanesForward = 0;         ///< `lanes:forward`; 0 when untagged (then split from `lanes`)
    int lanesBackward = 0;        ///< `lanes:backward`; 0 when untagged
    Sidewalk sidewalk = Sidewalk::Unknown;
    float sidewalkLeftWidth = 0;  ///< m, `sidewalk:left:width` / `sidewalk:both:width`; 0 when untagged
    float sidewalkRightWidth = 0; ///< m, `sidewalk:right:width` / `sidewalk:both:width`; 0 when untagged
    RoadSurface surface = RoadSurface::Unknown;  ///< `surface`; Unknown: the class's default
    FootwayKind footway = FootwayKind::None;
    bool oneway = false;
    bool laneMarkings = true;     ///< false for `lane_markings=no`
    bool overtaking = true;       ///< false for `overtaking=no`: a solid centre line
    bool area = false;            ///< `area=yes` on a way that is not closed (closed ones are Pedestrian areas)
    int layer = 0;
    bool bridge = false;
    bool tunnel = false;          ///< `tunnel=*` other than no (building_passage included)
    bool covered = false;         ///< `covered=yes`
    bool underground = false;     ///< `location=underground`
};

/// `crossing=*` of a crossing node, by how it is painted.
enum class CrossingKind : uint8_t { Zebra, Marked, Unmarked, TrafficSignals };

/// A pedestrian crossing: a `highway=crossing` node (or a `railway=crossing`), a vertex of the roads it crosses.
struct Crossing {
    int64_t osmId = 0;
    Vec2d position;
    CrossingKind kind = CrossingKind::Marked;
};

enum class RailKind : uint8_t { Rail, LightRail, Tram, Subway, Narrow };

struct Railway {
    int64_t osmId = 0;
    std::vector<Vec2d> centerline;
    RailKind kind = RailKind::Rail;
    float gauge = 1.435f;         ///< m, from `gauge` (mm)
    bool embedded = false;        ///< rails set in the street (`embedded=yes`, trams by default)
    int layer = 0;
    bool bridge = false;
    bool tunnel = false;
    bool covered = false;
    bool underground = false;
};

/// How a street lamp is held: `lamp_mount` / `support`.
enum class LampMount : uint8_t { Pole, BentMast, Wall, Suspended, Ground };

/// The shape of a lamp's head: from `lamp_type` / `light:shape` (and the mount).
enum class LampHead : uint8_t { Cobra, Globe, Lantern, Cone, Flat };

struct Lamp {
    int64_t osmId = 0;            ///< 0 if placed by urbis
    Vec2d position;
    float height = 6.0f;          ///< m, from `height` or `lamp_mount` defaults
    std::string lampType;         ///< `lamp_type` / `light:method`, as tagged
    LampMount mount = LampMount::Pole;
    LampHead head = LampHead::Cobra;
    float direction = -1.0f;      ///< degrees clockwise from north the head leans to; -1: towards the road
    int lightCount = 1;           ///< `light:count`
    float colourTemperature = 0;  ///< K, from `light:colour` or the lamp's method; 0 if unknown
};

/// `leaf_type` of a tree or a wood.
enum class LeafType : uint8_t { Unknown, Broadleaved, Needleleaved };
/// `leaf_cycle` of a tree or a wood.
enum class LeafCycle : uint8_t { Unknown, Deciduous, Evergreen };

struct Tree {
    int64_t osmId = 0;
    Vec2d position;
    float height = 8.0f;
    float crownDiameter = 5.0f;
    float circumference = 0;          ///< m, of the trunk (`circumference`); 0: untagged (by height)
    bool heightTagged = false;        ///< `height` (else a seeded variation of `height`)
    bool crownTagged = false;         ///< `diameter_crown` (else by height and shape)
    LeafType leafType = LeafType::Unknown;
    LeafCycle leafCycle = LeafCycle::Unknown;
    bool inRow = false;               ///< placed along a natural=tree_row way (osmId is the way's)
};

/// What covers an area of the ground, by the tag that says so (ground_cover in streets/ draws them).
enum class AreaKind : uint8_t {
    Park, Grass, Forest, Water, Residential, Commercial, Industrial, Pitch, Playground, Sand, Scrub,
    Parking, Pedestrian, Cemetery, Farmland
};

struct Area {
    int64_t osmId = 0;
    AreaKind kind = AreaKind::Park;
    RoadSurface surface = RoadSurface::Unknown;  ///< `surface` of paved areas (pedestrian, parking)
    int layer = 0;
    Polygon polygon;
    LeafType leafType = LeafType::Unknown;   ///< `leaf_type` of a wood, forest or park (the trees filled in)
    std::optional<float> ele;                ///< `ele` of a water body: its level, m above sea level
    /// A river mapped only as a line (waterway=river|stream|canal|drain|ditch): its centerline (local
    /// metres) in its OSM direction, the way it flows; `polygon` is the ribbon around it. Empty otherwise.
    std::vector<Vec2d> flowLine;
};

/// A longitude/latitude box in degrees, WGS84.
struct LonLatBox {
    bool valid = false;
    double minLon = 0, minLat = 0, maxLon = 0, maxLat = 0;
};

/// Geographic reference of a CityModel imported from OSM.
struct GeoOrigin {
    bool valid = false;
    double lat = 0, lon = 0;      ///< degrees, WGS84: the point at local (0, 0)
};

struct CityModel {
    std::vector<Building> buildings;
    std::vector<Road> roads;
    std::vector<Crossing> crossings;
    std::vector<Railway> railways;
    std::vector<Lamp> lamps;
    std::vector<Tree> trees;
    std::vector<Area> areas;
    GeoOrigin origin;
    std::string source;                        ///< file name, or "generated"
    LonLatBox headerBox;                       ///< the file's header box; invalid when it has none
    LonLatBox cropBox;                         ///< the box the import cropped to
    std::string cropBoxSource;                 ///< where cropBox came from: "bbox", "header" or "data_extent"
    ReasonLog dropped;                         ///< objects not kept, by reason
    ReasonLog repaired;                        ///< objects kept after a fix (geometry made valid, a tag ignored), by reason
    std::vector<std::string> warnings;         ///< one line each, for the user: what was repaired at some risk (a broken coastline)
    size_t buildingParts() const {
        size_t n = 0;
        for (const Building& b : buildings) n += b.isPart ? 1 : 0;
        return n;
    }
};

} // namespace urbis
