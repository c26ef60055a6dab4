#include "app/memory_json.h"

namespace urbis {

nlohmann::json memoryJson(const SceneMemory& memory) {
    nlohmann::json json = nlohmann::json::object();
    memory.forEach([&](const char* key, size_t bytes) { json[key] = bytes; });
    return json;
}

nlohmann::json memoryJson(const GpuMemory& memory) {
    nlohmann::json json = memoryJson(memory.scene);
    json["film"] = memory.film;
    json["rays"] = memory.rays;
    json["total"] = memory.total();
    return json;
}

} // namespace urbis
