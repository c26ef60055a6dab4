// The memory figures of --stats and bench as JSON, from the one description of the scene's arrays.
#pragma once

#include "gpu/gpu_backend.h"
#include "scene/scene.h"

#include <nlohmann/json.hpp>

namespace urbis {

/// {"bvh": bytes, "triangles": bytes, ... one key per scene array}.
nlohmann::json memoryJson(const SceneMemory& memory);

/// The scene's arrays on the device, then "film", "rays" and "total" (their sum).
nlohmann::json memoryJson(const GpuMemory& memory);

} // namespace urbis
