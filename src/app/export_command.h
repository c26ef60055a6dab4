// `urbis export`: the triangle twin of everything urbis draws, as glTF (.glb, .gltf) or OBJ, whole or
// in tiles, for other tools (Blender, game engines, CesiumJS through a tiler).
#pragma once

#include "app/scene_options.h"

#include <CLI/CLI.hpp>

#include <string>

namespace urbis {

struct ExportOptions {
    std::string out;            ///< .glb, .gltf or .obj
    float tileSize = 0;         ///< --tiles: metres a side; 0: one file
    std::string lod = "facades";///< "facades" (windows, rooms, balconies) or "mass" (a closed box per wall)
    std::string maxMemory;      ///< --max-memory
};

/// The command line of `urbis export`: the scene's options (those of `urbis render` that shape the
/// city, its camera and its sun) and the export's own.
struct ExportCommandLine {
    SceneCommandLine scene;
    ExportOptions options;
};

/// Registers the subcommand's options on `app`.
void addExportCommand(CLI::App& app, ExportCommandLine& commandLine);

/// Loads or generates the city, meshes its triangle twin at the level of detail asked for and writes
/// it (with --tiles: a file per tile named OUT_X_Z.EXT and the index OUT.tiles.json, written last),
/// then one line on stdout. Throws InputError.
void runExport(const ExportCommandLine& commandLine);

} // namespace urbis
