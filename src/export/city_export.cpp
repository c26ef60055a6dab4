#include "export/city_export.h"

#include "description/building_type_names.h"
#include "export/pbr_material.h"
#include "export/road_marking_mesh.h"
#include "geometry/terrain_intersect.h"
#include "scene/surface_part.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <set>

namespace urbis {

namespace {

/// The node a non-building triangle of part `part` belongs to.
const char* streetNodeOf(SurfacePart part) {
    switch (part) {
    case SurfacePart::Road: return "roads";
    case SurfacePart::Junction: return "junctions";
    case SurfacePart::Sidewalk:
    case SurfacePart::Curb: return "sidewalks";
    case SurfacePart::GroundCover: return "ground_cover";
    case SurfacePart::Water: return "water";
    case SurfacePart::BridgeDeck:
    case SurfacePart::Parapet:
    case SurfacePart::Pier: return "bridges";
    case SurfacePart::Ballast:
    case SurfacePart::Rail: return "railways";
    case SurfacePart::LampPole:
    case SurfacePart::LampHead:
    case SurfacePart::LampGlass: return "lamps";
    case SurfacePart::TreeTrunk:
    case SurfacePart::TreeCrown: return "trees";
    default: return "other";
    }
}

const char* roofShapeName(RoofShape shape) {
    static const char* const kNames[] = {"flat", "skillion", "gabled", "hipped", "pyramidal", "dome",
                                         "onion", "gambrel", "mansard", "round", "unknown"};
    static_assert(std::size(kNames) == size_t(RoofShape::Unknown) + 1, "a name per RoofShape");
    return kNames[size_t(shape)];
}

std::string hexColour(Rgb c) {
    const auto byte = [](float v) { return int(std::lround(std::fmin(std::fmax(v, 0.0f), 1.0f) * 255.0f)); };
    char text[8];
    std::snprintf(text, sizeof text, "#%02x%02x%02x", byte(c.r), byte(c.g), byte(c.b));
    return text;
}

/// A building's node: named by its OSM object, its tags as urbis read them.
ExportNode buildingNode(const Building& b, size_t index) {
    ExportNode node;
    node.whole = true;
    const char* type = b.osmId > 0 ? "way" : "relation";
    node.name = b.osmId == 0 ? "building/" + std::to_string(index)
                             : std::string("building/") + type + "/" + std::to_string(b.osmId < 0 ? -b.osmId : b.osmId);
    nlohmann::json tags = {{b.isPart ? "building:part" : "building", buildingTypeName(b.type)},
                           {"height", b.height},
                           {"roof:shape", roofShapeName(b.roofShape)},
                           {"building:colour", hexColour(b.wallColour)},
                           {"roof:colour", hexColour(b.roofColour)}};
    if (b.minHeight > 0) tags["min_height"] = b.minHeight;
    if (b.levels >= 0) tags["building:levels"] = b.levels;
    node.extras = {{"kind", "building"}, {"index", index}, {"tags", tags}};
    if (b.osmId != 0) {
        node.extras["osm_id"] = b.osmId < 0 ? -b.osmId : b.osmId;
        node.extras["osm_type"] = type;
    }
    return node;
}

/// Collects triangles into nodes and primitives, and the materials they use in first-use order.
class SceneCollector {
public:
    explicit SceneCollector(const std::vector<Material>& materials) : source_(materials) {}

    ExportPrimitive& primitiveOf(ExportNode& node, uint32_t material) {
        auto [it, inserted] = remap_.try_emplace(material, uint32_t(scene.materials.size()));
        if (inserted) scene.materials.push_back(pbrMaterialOf(source_[material], "material_" + std::to_string(material)));
        for (ExportPrimitive& p : node.primitives)
            if (p.material == it->second) return p;
        node.primitives.push_back({it->second, {}});
        return node.primitives.back();
    }

    ExportScene scene;

private:
    const std::vector<Material>& source_;
    std::map<uint32_t, uint32_t> remap_;
};

/// The road markings' node (export/road_marking_mesh.h), empty where no road is marked.
ExportNode roadMarkingNode(const CityMesh& mesh, SceneCollector& out) {
    ExportNode node;
    node.name = "road_markings";
    const TriangleMesh markings = roadMarkingMesh(mesh.roadSegments, mesh.mesh);
    std::set<uint32_t> roads;
    for (size_t k = 0; k < markings.size(); ++k) {
        out.primitiveOf(node, markings.info[k].material).triangles.push_back(markings.triangles[k]);
        roads.insert(markings.info[k].object);
    }
    node.extras = {{"kind", "road_markings"}, {"objects", roads.size()}, {"lift", kMarkingLift}};
    return node;
}

/// The flat ground: a square at y = 0 reaching `margin` past `bounds`.
ExportNode groundNode(const Bounds3f& bounds, float margin, uint32_t material, SceneCollector& out) {
    ExportNode node;
    node.name = "ground";
    node.extras = {{"kind", "ground"}};
    const float x0 = bounds.lo.x - margin, x1 = bounds.hi.x + margin, z0 = bounds.lo.z - margin, z1 = bounds.hi.z + margin;
    const Vec3f a{x0, 0, z0}, b{x1, 0, z0}, c{x1, 0, z1}, d{x0, 0, z1};
    // Counter-clockwise seen from above (+y): the glTF front face points up.
    std::vector<Triangle>& t = out.primitiveOf(node, material).triangles;
    t.push_back({a, d, c});
    t.push_back({a, c, b});
    return node;
}

/// The terrain's heightfield as two triangles per cell, each of the material at its centre.
ExportNode terrainNode(const TerrainField& terrain, SceneCollector& out) {
    ExportNode node;
    node.name = "terrain";
    const TerrainRecord& r = terrain.record;
    node.extras = {{"kind", "terrain"}, {"cell", r.cell}, {"samples", {r.nx, r.nz}}};
    const auto vertex = [&](uint32_t i, uint32_t j) {
        return Vec3f{r.x0 + r.cell * float(i), terrain.data[size_t(j) * r.nx + i], r.z0 + r.cell * float(j)};
    };
    for (uint32_t j = 0; j + 1 < r.nz; ++j)
        for (uint32_t i = 0; i + 1 < r.nx; ++i) {
            const Vec3f a = vertex(i, j), b = vertex(i + 1, j), c = vertex(i + 1, j + 1), d = vertex(i, j + 1);
            for (const Triangle& t : {Triangle{a, d, c}, Triangle{a, c, b}}) {
                const Vec3f n = normalize(cross(t.p1 - t.p0, t.p2 - t.p0));
                const uint32_t material = terrainMaterialAt(r, (t.p0 + t.p1 + t.p2) * (1.0f / 3.0f), n);
                out.primitiveOf(node, material).triangles.push_back(t);
            }
        }
    return node;
}

} // namespace

ExportScene exportSceneOf(const CityModel& city, const CityMesh& mesh, const TerrainField& terrain, const Camera& camera,
                          const Sun& sun) {
    SceneCollector out(mesh.materials);
    std::vector<ExportNode> buildings(city.buildings.size());
    std::map<std::string, ExportNode> streets;
    std::map<std::string, std::map<uint32_t, bool>> streetObjects;
    Bounds3f everything;
    for (size_t k = 0; k < mesh.mesh.size(); ++k) {
        const Triangle& t = mesh.mesh.triangles[k];
        const TriangleInfo info = mesh.mesh.info[k];
        everything.extend(primBounds(t));
        const uint32_t object = info.object;
        ExportNode* node = nullptr;
        // A building's parts lie before Road; a street triangle's object may be any number (a Road's
        // is its RoadSegment's index).
        if (object >= 1 && object <= buildings.size() && info.part < uint32_t(SurfacePart::Road)) {
            node = &buildings[object - 1];
            if (node->name.empty()) *node = buildingNode(city.buildings[object - 1], object - 1);
        } else {
            const char* kind = streetNodeOf(SurfacePart(info.part));
            node = &streets[kind];
            if (node->name.empty()) node->name = kind;
            streetObjects[kind][object] = true;
        }
        out.primitiveOf(*node, info.material).triangles.push_back(t);
    }
    ExportScene& scene = out.scene;
    for (ExportNode& b : buildings)
        if (!b.primitives.empty()) scene.nodes.push_back(std::move(b));
    for (auto& [kind, node] : streets) {
        node.extras = {{"kind", kind}, {"objects", streetObjects[kind].size()}};
        scene.nodes.push_back(std::move(node));
    }
    ExportNode markings = roadMarkingNode(mesh, out);
    if (!markings.primitives.empty()) scene.nodes.push_back(std::move(markings));
    if (terrain.empty()) {
        if (everything.empty()) everything.extend(Vec3f{0, 0, 0});
        scene.nodes.push_back(groundNode(everything, 100.0f, mesh.groundMaterial, out));
    } else {
        scene.nodes.push_back(terrainNode(terrain, out));
    }
    scene.camera = ExportCamera{camera.position, camera.forward, camera.up, 2.0f * std::atan(camera.tanHalfFovY), camera.aspect};
    // The disk's irradiance: its radiance over the cap's solid angle, 2 pi (1 - cos), the green channel's.
    scene.sunDirection = sun.direction;
    scene.sunIrradiance = sun.direction.y > 0 ? sun.radiance.y * 2.0f * 3.14159265f * (1.0f - sun.cosHalfAngle) : 0.0f;
    scene.extras = {{"generator", "urbis"}, {"source", city.source},
                    {"axes", "x east, y up, z south; metres"},
                    {"radiance_unit_cd_m2", kRadianceUnitCdPerM2},
                    {"buildings", city.buildings.size()}};
    // The sun in urbis units, for a renderer that takes the file's radiances as they are (bench/cycles).
    scene.extras["sun"] = {{"direction", {sun.direction.x, sun.direction.y, sun.direction.z}},
                           {"irradiance", scene.sunIrradiance}};
    if (city.origin.valid) scene.extras["origin"] = {{"lon", city.origin.lon}, {"lat", city.origin.lat}};
    return scene;
}

} // namespace urbis
