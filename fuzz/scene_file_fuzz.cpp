// libFuzzer target: bytes -> a scene file (JSON) -> sceneFromJson, the path `urbis render --scene`
// takes before any import. InputError is the clean answer to bad input; anything else (another
// exception, a crash, a sanitizer report) is a finding, and so is a description that does not
// survive its own round trip (written, read back, written again: the same JSON).
#include "description/scene_json.h"
#include "base/input_error.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    nlohmann::ordered_json json = nlohmann::ordered_json::parse(bytes, nullptr, false);
    if (json.is_discarded()) return 0;  // malformed JSON: readSceneFile's one line, tested apart
    try {
        const urbis::SceneDescription description = urbis::sceneFromJson(json, "fuzz.json");
        const nlohmann::ordered_json written = urbis::sceneToJson(description);
        if (urbis::sceneToJson(urbis::sceneFromJson(written, "fuzz.json")) != written) std::abort();
    } catch (const urbis::InputError&) {
    }
    return 0;
}
