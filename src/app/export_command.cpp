#include "app/export_command.h"

#include "base/step_timer.h"
#include "app/memory_limit.h"
#include "io/output_paths.h"
#include "prepare/scene_city.h"
#include "base/input_error.h"
#include "citygen/city_terrain.h"
#include "description/celestial_parts.h"
#include "description/scene_json.h"
#include "description/scene_parts.h"
#include "export/city_export.h"
#include "export/export_tiles.h"
#include "export/gltf_file.h"
#include "export/obj_file.h"
#include "io/atomic_file.h"

#include <cstdio>
#include <filesystem>

namespace urbis {

void addExportCommand(CLI::App& app, ExportCommandLine& line) {
    CLI::App* cmd = app.add_subcommand("export", "Write the triangle twin of the city (buildings, streets, lamps, trees, "
                                                 "ground or terrain) as glTF (.glb, .gltf) or OBJ");
    line.scene.addOptions(*cmd, {"--osm", "--bbox", "--building-height-range", "--metres-per-level", "--height-scale",
                                 "--buildings", "--seed", "--camera", "--camera-geo", "--fov", "--width", "--height",
                                 "--time", "--location", "--sun", "--no-streets", "--traffic", "--terrain", "--dem"});
    ExportOptions& o = line.options;
    cmd->add_option("--out", o.out, "File to write; the format follows the extension: .glb, .gltf or .obj (with its .mtl)")
        ->required();
    cmd->add_option("--tiles", o.tileSize, "Split into square tiles of SIZE metres: a file per tile and an index JSON")
        ->check([](const std::string& text) -> std::string {
            float size = 0;
            return CLI::detail::lexical_cast(text, size) && size > 0 ? "" : "the tile size must be a positive number of metres";
        });
    cmd->add_option("--lod", o.lod, "Level of detail: facades (windows, rooms' fronts, balconies) or mass (plain walls)")
        ->check(CLI::IsMember({"facades", "mass"}))->capture_default_str();
    cmd->add_option("--max-memory", o.maxMemory,
                    "Host memory the run may take, e.g. 8G, 512M (default: 80 % of the memory available)");
}

namespace {

/// Where tile (x, z) of an export to `out` goes: city.glb -> city_X_Z.glb.
std::string tilePathOf(const std::string& out, int x, int z) {
    const std::filesystem::path p(out);
    return (p.parent_path() / (p.stem().string() + "_" + std::to_string(x) + "_" + std::to_string(z) + p.extension().string()))
        .string();
}

std::string indexPathOf(const std::string& out) {
    return std::filesystem::path(out).replace_extension(".tiles.json").string();
}

/// Writes `scene` to `path` in the format of its extension (checked before: .glb, .gltf or .obj).
void writeExport(const ExportScene& scene, const std::string& path) {
    const std::string ext = std::filesystem::path(path).extension().string();
    if (ext == ".obj" || ext == ".OBJ") writeObjFile(scene, path);
    else writeGltfFile(scene, path, ext == ".glb" || ext == ".GLB");
}

/// The export's geometry modes: every kind as its triangle twin; walls plain for the mass model.
GeometryModes exportModesOf(const std::string& lod) {
    GeometryModes m{Representation::Triangles, Representation::Triangles, Representation::Triangles, Representation::Triangles};
    if (lod == "mass") m.walls = Representation::Plain;
    return m;
}

} // namespace

void runExport(const ExportCommandLine& line) {
    const auto start = SteadyClock::now();
    const ExportOptions& o = line.options;
    checkOutputPath("--out", o.out, {".glb", ".gltf", ".obj"});
    checkOutputPath("--save-scene", line.scene.saveScenePath(), {".json"});
    SceneDescription d = line.scene.resolve();
    if (d.planet) throw InputError("export: a planet cannot be exported (cities only)", FailureKind::Usage);
    d.geometry.modes = exportModesOf(o.lod);
    const size_t limit = memoryLimit(o.maxMemory);

    CityModel city = loadSceneCity(d);
    CityMeshOptions meshOptions = cityMeshOptionsOf(d, limit);
    meshOptions.litRoomLooks = true;
    CityMesh mesh = meshCity(city, meshOptions);
    const TerrainField terrain = cityTerrainOf(d.terrain, city.origin, mesh);
    const Camera camera =
        cameraOf(d.camera, float(d.film.width) / float(d.film.height), city.origin, mesh.framingPieces, groundOf(terrain));
    ExportScene scene = exportSceneOf(city, mesh, terrain, camera, celestialLightsOf(d, city.origin).sun);
    scene.extras["lod"] = o.lod;
    if (!line.scene.saveScenePath().empty()) writeSceneFile(d, line.scene.saveScenePath());

    std::string files = o.out;
    if (o.tileSize > 0) {
        nlohmann::json index = {{"tile_size", o.tileSize}, {"extras", scene.extras}, {"tiles", nlohmann::json::array()}};
        for (const ExportTile& tile : splitIntoTiles(scene, o.tileSize)) {
            const std::string path = tilePathOf(o.out, tile.x, tile.z);
            writeExport(tile.scene, path);
            index["tiles"].push_back({{"file", std::filesystem::path(path).filename().string()}, {"x", tile.x}, {"z", tile.z},
                                      {"nodes", tile.scene.nodes.size()}, {"triangles", tile.scene.triangleCount()}});
        }
        files = indexPathOf(o.out);
        writeTextFileAtomically(files, index.dump(2) + "\n");
    } else {
        writeExport(scene, o.out);
    }
    std::printf("urbis: wrote %s (%zu nodes, %zu triangles, %zu materials) in %.2f s\n", files.c_str(), scene.nodes.size(),
                scene.triangleCount(), scene.materials.size(),
                secondsSince(start));
}

} // namespace urbis
