#include "viewer/view_script.h"

#include "base/input_error.h"
#include "description/scene_json.h"

#include <algorithm>
#include <cmath>

namespace urbis {

namespace {

using json = nlohmann::ordered_json;

/// Reads one step, naming `file` and the step's path in every problem.
class StepReader {
public:
    StepReader(const json& node, std::string where) : node_(node), where_(std::move(where)) {
        if (!node.is_object()) fail("", "expected an object");
        for (const auto& [key, value] : node.items())
            if (std::find(std::begin(kKeys), std::end(kKeys), key) == std::end(kKeys))
                fail(key, "unknown key (keys: frame, load, set, mode, input, undo, jump, goto, screenshot, width, height, spp, save_scene, quit)");
    }

    ScriptStep read() {
        ScriptStep s;
        s.frame = uint32_t(number("frame", 0, 1e9, true).value_or(0));
        s.load = text("load");
        if (node_.contains("set")) {
            if (!node_["set"].is_object()) fail("set", "expected an object shaped like a scene file");
            s.set = node_["set"];
        }
        if (node_.contains("mode")) s.mode = modeOf(node_["mode"], "mode");
        if (node_.contains("input")) s.input = inputOf(node_["input"]);
        s.undo = flag("undo");
        if (node_.contains("jump")) {
            const json& j = node_["jump"];
            if (!j.is_array() || j.size() != 3 || !j[0].is_number() || !j[1].is_number() || !j[2].is_number())
                fail("jump", "expected [LON, LAT, ALTITUDE]");
            const double lon = j[0].get<double>(), lat = j[1].get<double>(), alt = j[2].get<double>();
            if (!(std::abs(lon) <= 180 && std::abs(lat) <= 90 && alt >= 0 && alt <= 1e6))
                fail("jump", "need |LON| <= 180, |LAT| <= 90 degrees and 0 <= ALTITUDE <= 1e6 metres");
            s.jump = std::array<double, 3>{lon, lat, alt};
        }
        s.goTo = text("goto", "the name of an OSM feature");
        s.screenshot = text("screenshot");
        s.width = uint32_t(number("width", 1, 65536, true).value_or(0));
        s.height = uint32_t(number("height", 1, 65536, true).value_or(0));
        s.spp = uint32_t(number("spp", 1, 1 << 20, true).value_or(0));
        if ((s.width || s.height || s.spp) && s.screenshot.empty()) fail("width", "width, height and spp belong to a screenshot");
        s.saveScene = text("save_scene");
        s.quit = flag("quit");
        return s;
    }

private:
    static constexpr const char* kKeys[] = {"frame", "load", "set", "mode", "input", "undo", "jump", "goto", "screenshot",
                                            "width", "height", "spp", "save_scene", "quit"};

    [[noreturn]] void fail(const std::string& key, const std::string& problem) const {
        throw InputError(where_ + (key.empty() ? "" : "." + key) + ": " + problem);
    }

    std::optional<double> number(const char* key, double lo, double hi, bool integer) const {
        if (!node_.contains(key)) return std::nullopt;
        const json& n = node_[key];
        if (integer ? !n.is_number_integer() : !n.is_number()) fail(key, integer ? "expected an integer" : "expected a number");
        const double x = n.get<double>();
        const auto bound = [integer](double b) { return integer ? std::to_string(int64_t(b)) : json(b).dump(); };
        if (!(x >= lo && x <= hi)) fail(key, n.dump() + " is out of range " + bound(lo) + ".." + bound(hi));
        return x;
    }

    bool flag(const char* key) const {
        if (!node_.contains(key)) return false;
        if (!node_[key].is_boolean()) fail(key, "expected true or false");
        return node_[key].get<bool>();
    }

    std::string text(const char* key, const char* what = "a file name") const {
        if (!node_.contains(key)) return {};
        if (!node_[key].is_string() || node_[key].get<std::string>().empty()) fail(key, std::string("expected ") + what);
        return node_[key].get<std::string>();
    }

    CameraMode modeOf(const json& n, const std::string& key) const {
        if (n == "orbit") return CameraMode::Orbit;
        if (n == "fly") return CameraMode::Fly;
        fail(key, "expected \"orbit\" or \"fly\"");
    }

    CameraInput inputOf(const json& n) const {
        if (!n.is_object()) fail("input", "expected an object of keys, mouse, scroll and seconds");
        CameraInput in;
        for (const auto& [key, value] : n.items()) {
            const std::string path = "input." + key;
            if (key == "keys") {
                if (!value.is_string()) fail(path, "expected a string of the keys W, A, S, D, Q, E held");
                for (char c : value.get<std::string>()) {
                    switch (c) {
                    case 'W': in.forward = true; break;
                    case 'S': in.back = true; break;
                    case 'A': in.left = true; break;
                    case 'D': in.right = true; break;
                    case 'E': in.up = true; break;
                    case 'Q': in.down = true; break;
                    default: fail(path, std::string("'") + c + "' is none of the keys W, A, S, D, Q, E");
                    }
                }
            } else if (key == "mouse") {
                if (!value.is_array() || value.size() != 2 || !value[0].is_number() || !value[1].is_number())
                    fail(path, "expected [DX, DY] in pixels");
                in.dragging = true;
                in.mouseDx = value[0].get<float>();
                in.mouseDy = value[1].get<float>();
            } else if (key == "scroll") {
                if (!value.is_number()) fail(path, "expected a number of wheel steps");
                in.scroll = value.get<float>();
            } else if (key == "seconds") {
                if (!value.is_number() || !(value.get<double>() >= 0 && value.get<double>() <= 3600))
                    fail(path, "expected seconds in 0..3600");
                in.seconds = value.get<float>();
            } else {
                fail(path, "unknown key (keys: keys, mouse, scroll, seconds)");
            }
        }
        return in;
    }

    const json& node_;
    std::string where_;
};

} // namespace

std::vector<ScriptStep> scriptFromJson(const json& root, const std::string& file) {
    if (!root.is_object() || !root.contains("steps") || root.size() != 1)
        throw InputError(file + ": expected an object {\"steps\": [...]} (docs/viewer.md)");
    const json& steps = root["steps"];
    if (!steps.is_array()) throw InputError(file + ": steps: expected an array of steps");
    std::vector<ScriptStep> out;
    for (size_t i = 0; i < steps.size(); ++i)
        out.push_back(StepReader(steps[i], file + ": steps[" + std::to_string(i) + "]").read());
    std::stable_sort(out.begin(), out.end(), [](const ScriptStep& a, const ScriptStep& b) { return a.frame < b.frame; });
    return out;
}

std::vector<ScriptStep> readScriptFile(const std::string& path) { return scriptFromJson(readJsonFile(path, "script"), path); }

} // namespace urbis
