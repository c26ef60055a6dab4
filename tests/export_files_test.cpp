// The export's files read back: glTF through tinygltf, OBJ by its lines, tiles by their sum; every
// count compared with the triangle twin urbis renders (citygen's mesh) and the road markings laid on
// it (export/road_marking_mesh.h), not with the exporter's own.
#include "cli_support.h"

#include "citygen/city_mesher.h"
#include "export/city_export.h"
#include "export/export_tiles.h"
#include "export/gltf_file.h"
#include "export/obj_file.h"
#include "export/road_marking_mesh.h"
#include "osm/osm_import.h"
#include "scene/surface_part.h"

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <map>
#include <set>
#include <sstream>

using namespace urbis;
namespace fs = std::filesystem;

namespace {

const std::string kVillage = URBIS_OSMNX_DATA "/planet_10.068,48.135_10.071,48.137.osm";

/// The village's twin (every kind as triangles, lit windows at 21 h) and its export.
struct VillageExport {
    CityModel city;
    CityMesh mesh;
    ExportScene scene;
    std::set<uint32_t> buildingObjects, materials;   ///< of the twin's triangles
    std::map<uint32_t, Bounds3f> buildingBounds;     ///< by object id
    size_t buildingTriangles = 0;
    size_t markingTriangles = 0;                     ///< the node road_markings's
};

const VillageExport& village() {
    static const VillageExport v = [] {
        VillageExport e;
        e.city = importOsm(kVillage, ImportOptions{});
        CityMeshOptions options;
        options.geometry = {Representation::Triangles, Representation::Triangles, Representation::Triangles,
                            Representation::Triangles};
        options.hour = 21;
        options.litRoomLooks = true;
        e.mesh = meshCity(e.city, options);
        const Camera camera = makeLookAtCamera({-150, 80, 150}, {0, 0, 0}, 40, 1.5f);
        e.scene = exportSceneOf(e.city, e.mesh, {}, camera, makeSun(35, 200, 0.27f, {1, 1, 1}));
        for (size_t k = 0; k < e.mesh.mesh.size(); ++k) {
            const TriangleInfo info = e.mesh.mesh.info[k];
            e.materials.insert(info.material);
            if (info.object >= 1 && info.object <= e.city.buildings.size() && info.part < uint32_t(SurfacePart::Road)) {
                e.buildingObjects.insert(info.object);
                e.buildingBounds[info.object].extend(primBounds(e.mesh.mesh.triangles[k]));
                ++e.buildingTriangles;
            }
        }
        e.materials.insert(e.mesh.groundMaterial);
        const TriangleMesh markings = roadMarkingMesh(e.mesh.roadSegments, e.mesh.mesh);
        e.markingTriangles = markings.size();
        for (const TriangleInfo& info : markings.info) e.materials.insert(info.material);
        return e;
    }();
    return v;
}

size_t trianglesOf(const tinygltf::Model& model, const tinygltf::Mesh& mesh) {
    size_t n = 0;
    for (const tinygltf::Primitive& p : mesh.primitives) n += model.accessors[size_t(p.indices)].count / 3;
    return n;
}

tinygltf::Model readGltf(const fs::path& path) {
    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    std::string err, warn;
    const bool ok = path.extension() == ".glb" ? loader.LoadBinaryFromFile(&model, &err, &warn, path.string())
                                               : loader.LoadASCIIFromFile(&model, &err, &warn, path.string());
    EXPECT_TRUE(ok) << path << ": " << err;
    return model;
}

/// The twin's counts in a glTF file of the whole village: a mesh per node, a node per mesh plus the
/// camera and the sun, every triangle, the materials the triangles use, each building's OSM id and
/// its box (the file's accessor bounds against the twin's triangles: 1 mm).
void expectVillageCounts(const tinygltf::Model& model) {
    const VillageExport& v = village();
    const size_t buildings = v.buildingObjects.size();
    ASSERT_GT(buildings, 20u);
    EXPECT_EQ(model.meshes.size(), v.scene.nodes.size());
    EXPECT_EQ(model.nodes.size(), v.scene.nodes.size() + 2) << "a node per mesh, the camera and the sun";
    EXPECT_EQ(model.materials.size(), v.materials.size());
    EXPECT_EQ(model.cameras.size(), 1u);
    EXPECT_EQ(model.lights.size(), 1u);
    size_t triangles = 0, buildingNodes = 0;
    for (const tinygltf::Node& node : model.nodes) {
        if (node.mesh < 0) continue;
        const size_t n = trianglesOf(model, model.meshes[size_t(node.mesh)]);
        triangles += n;
        if (!node.extras.Has("osm_id")) continue;
        ++buildingNodes;
        const size_t index = size_t(node.extras.Get("index").GetNumberAsInt());
        const Building& b = v.city.buildings[index];
        EXPECT_EQ(node.extras.Get("osm_id").GetNumberAsDouble(), double(b.osmId < 0 ? -b.osmId : b.osmId));
        EXPECT_EQ(node.name, std::string("building/") + (b.osmId > 0 ? "way/" : "relation/") +
                                 std::to_string(b.osmId < 0 ? -b.osmId : b.osmId));
        Bounds3f fromFile;
        for (const tinygltf::Primitive& p : model.meshes[size_t(node.mesh)].primitives) {
            const tinygltf::Accessor& a = model.accessors[size_t(p.attributes.at("POSITION"))];
            fromFile.extend(Vec3f{float(a.minValues[0]), float(a.minValues[1]), float(a.minValues[2])});
            fromFile.extend(Vec3f{float(a.maxValues[0]), float(a.maxValues[1]), float(a.maxValues[2])});
        }
        const Bounds3f twin = v.buildingBounds.at(uint32_t(index + 1));
        for (int axis = 0; axis < 3; ++axis) {
            EXPECT_NEAR(fromFile.lo[axis], twin.lo[axis], 1e-3f) << node.name;
            EXPECT_NEAR(fromFile.hi[axis], twin.hi[axis], 1e-3f) << node.name;
        }
    }
    EXPECT_EQ(buildingNodes, buildings);
    EXPECT_EQ(triangles, v.mesh.mesh.size() + v.markingTriangles + 2) << "the twin's triangles, the markings and the ground's two";
    const tinygltf::Value& origin = model.asset.extras.Get("origin");
    EXPECT_DOUBLE_EQ(origin.Get("lon").GetNumberAsDouble(), v.city.origin.lon);
    EXPECT_DOUBLE_EQ(origin.Get("lat").GetNumberAsDouble(), v.city.origin.lat);
}

} // namespace

TEST(ExportFiles, VillageGlbReadBackHasTheTwinsCounts) {
    const fs::path dir = test::scratchDir("export_glb");
    writeGltfFile(village().scene, (dir / "village.glb").string(), true);
    EXPECT_FALSE(fs::exists(dir / "village.glb.tmp"));
    expectVillageCounts(readGltf(dir / "village.glb"));
}

TEST(ExportFiles, VillageGltfTextStandsAloneAndHasTheTwinsCounts) {
    const fs::path dir = test::scratchDir("export_gltf");
    writeGltfFile(village().scene, (dir / "village.gltf").string(), false);
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1) << "no .bin beside it";
    expectVillageCounts(readGltf(dir / "village.gltf"));
}

TEST(ExportFiles, LitWindowsEmitAndGlassTransmits) {
    // At 21 h some rooms are lit (citygen/window_schedule.h): their material emits; the panes transmit.
    const fs::path dir = test::scratchDir("export_emission");
    writeGltfFile(village().scene, (dir / "v.glb").string(), true);
    const tinygltf::Model model = readGltf(dir / "v.glb");
    size_t emitting = 0, transmitting = 0;
    for (const tinygltf::Material& m : model.materials) {
        emitting += m.extensions.count("KHR_materials_emissive_strength");
        transmitting += m.extensions.count("KHR_materials_transmission");
    }
    EXPECT_GE(emitting, 1u);
    EXPECT_GE(transmitting, 1u);
}

TEST(ExportFiles, VillageObjReadBackHasTheTwinsCounts) {
    const fs::path dir = test::scratchDir("export_obj");
    writeObjFile(village().scene, (dir / "village.obj").string());
    std::istringstream obj(test::readFile(dir / "village.obj")), mtl(test::readFile(dir / "village.mtl"));
    size_t objects = 0, vertices = 0, faces = 0, badFaces = 0;
    std::set<std::string> used, defined;
    for (std::string line; std::getline(obj, line);) {
        std::istringstream s(line);
        std::string key;
        s >> key;
        if (key == "o") ++objects;
        else if (key == "v") ++vertices;
        else if (key == "usemtl") used.insert(line.substr(7));
        else if (key == "f") {
            ++faces;
            for (size_t i = 0, index = 0; i < 3; ++i) badFaces += !(s >> index) || index < 1 || index > vertices;
        }
    }
    for (std::string line; std::getline(mtl, line);)
        if (line.rfind("newmtl ", 0) == 0) defined.insert(line.substr(7));
    const VillageExport& v = village();
    EXPECT_EQ(objects, v.scene.nodes.size());
    EXPECT_EQ(faces, v.mesh.mesh.size() + v.markingTriangles + 2);
    EXPECT_EQ(badFaces, 0u) << "a face refers to a vertex not yet written";
    EXPECT_EQ(used.size(), v.materials.size());
    EXPECT_EQ(used, defined);
}

TEST(ExportFiles, TilesKeepEveryTriangleAndEachBuildingWhole) {
    const VillageExport& v = village();
    const std::vector<ExportTile> tiles = splitIntoTiles(v.scene, 60.0f);
    ASSERT_GT(tiles.size(), 3u) << "the village is some 220 m across";
    size_t triangles = 0;
    std::map<std::string, int> buildingTiles;
    for (const ExportTile& tile : tiles) {
        triangles += tile.scene.triangleCount();
        std::set<uint32_t> used;
        for (const ExportNode& node : tile.scene.nodes) {
            if (node.whole) ++buildingTiles[node.name];
            for (const ExportPrimitive& p : node.primitives) used.insert(p.material);
            const Vec3f c = node.bounds().centre();
            if (node.whole) {
                EXPECT_TRUE(c.x >= float(tile.x) * 60.0f && c.x < float(tile.x + 1) * 60.0f) << node.name;
                EXPECT_TRUE(c.z >= float(tile.z) * 60.0f && c.z < float(tile.z + 1) * 60.0f) << node.name;
            }
        }
        EXPECT_EQ(used.size(), tile.scene.materials.size()) << "a tile keeps only the materials it uses";
        EXPECT_TRUE(tile.scene.extras.contains("origin"));
    }
    EXPECT_EQ(triangles, v.scene.triangleCount());
    EXPECT_EQ(buildingTiles.size(), v.buildingObjects.size());
    for (const auto& [name, n] : buildingTiles) EXPECT_EQ(n, 1) << name << " split across tiles";
}

TEST(ExportFiles, TerrainIsTwoTrianglesACellOfItsMaterials) {
    // A 5 x 4 heightfield rising 3 m a sample along x: 12 cells, their triangles at the samples' heights.
    std::vector<float> heights;
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 5; ++i) heights.push_back(3.0f * float(i));
    TerrainField terrain = TerrainField::fromSamples(-20, -15, 10, 5, 4, heights);
    terrain.record.material = uint32_t(village().mesh.materials.size());
    CityMesh mesh = village().mesh;
    for (uint32_t m = 0; m < uint32_t(TerrainMaterial::Count); ++m) mesh.materials.push_back(Material{});
    const ExportScene scene = exportSceneOf(village().city, mesh, terrain, makeLookAtCamera({0, 50, 50}, {}, 40, 1), Sun{});
    const ExportNode& node = scene.nodes.back();
    ASSERT_EQ(node.name, "terrain");
    EXPECT_EQ(node.triangleCount(), 2u * 4u * 3u);
    for (const ExportPrimitive& p : node.primitives)
        for (const Triangle& t : p.triangles)
            for (const Vec3f& v : {t.p0, t.p1, t.p2}) EXPECT_FLOAT_EQ(v.y, 3.0f * (v.x + 20.0f) / 10.0f);
    EXPECT_FALSE(std::any_of(scene.nodes.begin(), scene.nodes.end(), [](const ExportNode& n) { return n.name == "ground"; }));
    EXPECT_EQ(scene.sunIrradiance, 0.0f) << "a sun of no radiance is not exported";
}
