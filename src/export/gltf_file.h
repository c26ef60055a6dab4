// An ExportScene as glTF 2.0 through tinygltf: binary (.glb) or JSON with its buffer embedded (.gltf).
#pragma once

#include "export/export_scene.h"

#include <string>

namespace urbis {

/// Writes `scene` to `path` through a temporary: .glb binary, .gltf text (the buffer a base64 data
/// URI, so that the file stands alone). A node and a mesh per ExportNode (its extras as the node's),
/// a primitive per material (indexed positions; clients compute flat normals), materials double
/// sided with KHR_materials_transmission / _ior / _emissive_strength where they need them, a
/// perspective camera node "camera" and, while the sun is up, a KHR_lights_punctual sun "sun" (in
/// lux). The asset's extras are the scene's. Throws InputError naming `path` when it cannot be written.
void writeGltfFile(const ExportScene& scene, const std::string& path, bool binary);

} // namespace urbis
