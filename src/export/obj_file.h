// An ExportScene as Wavefront OBJ with its MTL beside it, for tools without glTF.
#pragma once

#include "export/export_scene.h"

#include <string>

namespace urbis {

/// Writes `scene` to `path` (.obj) and its materials to the same name with .mtl, each through a
/// temporary (the .mtl first): an `o` per node with its extras as a `# extras` comment line, `usemtl`
/// per primitive, welded vertices; the MTL's Kd, Ke, Ni, d and the PBR extension's Pr and Pm. The
/// asset's extras open the file as a comment. No camera or sun: OBJ has neither. Throws InputError
/// naming the file that cannot be written.
void writeObjFile(const ExportScene& scene, const std::string& path);

/// The .mtl beside an .obj `path`: its extension replaced.
std::string mtlPathOf(const std::string& objPath);

} // namespace urbis
