#include "description/scene_json.h"

#include "description/animation_json.h"
#include "description/building_type_names.h"
#include "description/scene_checks.h"
#include "description/scene_fields.h"
#include "io/atomic_file.h"
#include "base/input_error.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <type_traits>
#include <vector>

namespace urbis {

namespace {

using json = nlohmann::ordered_json;

/// The shortest decimal text that reads back as `value`, without an exponent (1000000, not 1e+06).
template <typename T>
std::string numberText(T value) {
    char text[400];
    std::to_chars_result result;
    if constexpr (std::is_floating_point_v<T>) result = std::to_chars(text, text + sizeof text, value, std::chars_format::fixed);
    else result = std::to_chars(text, text + sizeof text, value);
    auto [end, ec] = result;
    return ec == std::errc() ? std::string(text, end) : std::to_string(value);
}

/// Reads fields from a JSON object tree, following visitSceneFields; every problem is an
/// InputError "FILE: KEY.PATH: problem".
class FieldReader {
public:
    FieldReader(const json& root, const std::string& file) : file_(file) {
        if (!root.is_object()) throw InputError(file_ + ": expected a JSON object of the sections source, camera, ...");
        frames_.push_back({&root, "", {}});
    }

    /// Fails on the keys of the innermost object that no field named.
    void finish() { leave(); }

    template <typename F>
    void object(const char* key, F&& fields) {
        const json* node = child(key);
        if (!node) return;
        if (!node->is_object()) fail(key, "expected an object");
        enter(key, *node);
        fields();
        leave();
    }

    template <typename T, typename F>
    void optionalObject(const char* key, std::optional<T>& value, F&& fields) {
        const json* node = child(key);
        if (!node) return;
        if (node->is_null()) {
            value.reset();
            return;
        }
        if (!node->is_object()) fail(key, "expected an object or null");
        value = T{};
        enter(key, *node);
        fields(*value);
        leave();
    }

    template <typename T>
    void number(const char* key, T& value, std::type_identity_t<T> lo, std::type_identity_t<T> hi) {
        if (const json* node = child(key)) value = numberIn(*node, key, lo, hi);
    }

    void vec3(const char* key, Vec3f& value, float lo, float hi) {
        if (const json* node = child(key)) value = vec3In(*node, key, lo, hi, "expected an array of 3 numbers");
    }

    void optionalVec3(const char* key, std::optional<Vec3f>& value, float lo, float hi) {
        const json* node = child(key);
        if (!node) return;
        if (node->is_null()) value.reset();
        else value = vec3In(*node, key, lo, hi, "expected null or an array of 3 numbers");
    }

    template <typename T, size_t N>
    void optionalArray(const char* key, std::optional<std::array<T, N>>& value, T lo, T hi) {
        const json* node = child(key);
        if (!node) return;
        if (node->is_null()) {
            value.reset();
            return;
        }
        if (!node->is_array() || node->size() != N) fail(key, "expected null or an array of " + std::to_string(N) + " numbers");
        std::array<T, N> a{};
        for (size_t i = 0; i < N; ++i) a[i] = numberIn((*node)[i], key + ("[" + std::to_string(i) + "]"), lo, hi);
        value = a;
    }

    void text(const char* key, std::string& value) {
        const json* node = child(key);
        if (!node) return;
        if (!node->is_string()) fail(key, "expected a string");
        value = node->get<std::string>();
    }

    void boolean(const char* key, bool& value) {
        const json* node = child(key);
        if (!node) return;
        if (!node->is_boolean()) fail(key, "expected true or false");
        value = node->get<bool>();
    }

    void choice(const char* key, std::string& value, std::span<const char* const> names) {
        const json* node = child(key);
        if (!node) return;
        std::string list;
        for (const char* name : names) {
            list += (list.empty() ? "" : ", ") + std::string(name);
            if (node->is_string() && node->get<std::string>() == name) {
                value = name;
                return;
            }
        }
        fail(key, "expected one of " + list);
    }

    void choiceList(const char* key, std::vector<std::string>& value, std::span<const char* const> names) {
        const json* node = child(key);
        if (!node) return;
        std::string list;
        for (const char* name : names) list += (list.empty() ? "" : ", ") + std::string(name);
        if (!node->is_array()) fail(key, "expected an array of names out of " + list);
        std::vector<std::string> chosen;
        for (size_t i = 0; i < node->size(); ++i) {
            const json& item = (*node)[i];
            const std::string path = key + ("[" + std::to_string(i) + "]");
            const bool known = item.is_string() && std::find(names.begin(), names.end(), item.get<std::string>()) != names.end();
            if (!known) fail(path, "expected one of " + list);
            if (std::find(chosen.begin(), chosen.end(), item.get<std::string>()) != chosen.end()) fail(path, "named twice");
            chosen.push_back(item.get<std::string>());
        }
        value = std::move(chosen);
    }

    template <typename E, typename Names>
    void enumeration(const char* key, E& value, const Names& names) {
        const json* node = child(key);
        if (!node) return;
        std::string list;
        for (const auto& [name, e] : names) {
            list += (list.empty() ? "" : ", ") + std::string(name);
            if (node->is_string() && node->get<std::string>() == name) {
                value = e;
                return;
            }
        }
        fail(key, "expected one of " + list);
    }

    void colourMap(const char* key, std::map<std::string, Vec3f>& value) {
        const json* node = child(key);
        if (!node) return;
        if (!node->is_object()) fail(key, "expected an object of building type -> [r, g, b]");
        value.clear();
        for (const auto& [type, colour] : node->items()) {
            const std::string path = std::string(key) + "." + type;
            if (!buildingTypeNamed(type)) fail(path, "unknown building type (types: " + buildingTypeNameList() + ")");
            value[type] = vec3In(colour, path, 0.0f, 1.0f, "expected an array of 3 numbers");
        }
    }

    void animation(const char* key, AnimationDescription& value) {
        if (const json* node = child(key)) value = animationFromJson(*node, file_, pathOf(key));
    }

private:
    struct Frame {
        const json* node;
        std::string path;                 ///< of this object; empty at the top
        std::vector<std::string> known;   ///< the keys the fields named
    };

    std::string pathOf(const std::string& key) const {
        return frames_.back().path.empty() ? key : frames_.back().path + "." + key;
    }

    [[noreturn]] void fail(const std::string& key, const std::string& problem) const {
        throw InputError(file_ + ": " + pathOf(key) + ": " + problem);
    }

    /// The value under `key` in the innermost object, or nullptr when the file leaves it out.
    const json* child(const char* key) {
        Frame& frame = frames_.back();
        frame.known.emplace_back(key);
        auto it = frame.node->find(key);
        return it == frame.node->end() ? nullptr : &*it;
    }

    void enter(const char* key, const json& node) { frames_.push_back({&node, pathOf(key), {}}); }

    void leave() {
        const Frame& frame = frames_.back();
        for (const auto& [key, value] : frame.node->items())
            if (std::find(frame.known.begin(), frame.known.end(), key) == frame.known.end()) fail(key, "unknown key");
        frames_.pop_back();
    }

    template <typename T>
    T numberIn(const json& node, const std::string& key, T lo, T hi) const {
        const std::string range = numberText(lo) + ".." + numberText(hi);
        if constexpr (std::is_integral_v<T>) {
            if (!node.is_number_integer()) fail(key, "expected an integer");
            const bool inRange = node.is_number_unsigned()
                                     ? node.get<uint64_t>() >= uint64_t(lo) && node.get<uint64_t>() <= uint64_t(hi)
                                     : node.get<int64_t>() >= int64_t(lo) && node.get<int64_t>() <= int64_t(hi);
            if (!inRange) fail(key, node.dump() + " is out of range " + range);
            return node.is_number_unsigned() ? T(node.get<uint64_t>()) : T(node.get<int64_t>());
        } else {
            if (!node.is_number()) fail(key, "expected a number");
            const double x = node.get<double>();
            if (!(x >= double(lo) && x <= double(hi))) fail(key, node.dump() + " is out of range " + range);
            return T(x);
        }
    }

    Vec3f vec3In(const json& node, const std::string& key, float lo, float hi, const char* expected) const {
        if (!node.is_array() || node.size() != 3) fail(key, expected);
        Vec3f v;
        for (int i = 0; i < 3; ++i) v[i] = numberIn(node[size_t(i)], key + "[" + std::to_string(i) + "]", lo, hi);
        return v;
    }

    std::string file_;
    std::vector<Frame> frames_;
};

/// Writes every field into a JSON object tree, following visitSceneFields.
class FieldWriter {
public:
    json root = json::object();

    template <typename F>
    void object(const char* key, F&& fields) {
        json* outer = current_;
        current_ = &((*outer)[key] = json::object());
        fields();
        current_ = outer;
    }

    template <typename T, typename F>
    void optionalObject(const char* key, const std::optional<T>& value, F&& fields) {
        if (!value) {
            (*current_)[key] = nullptr;
            return;
        }
        object(key, [&] { fields(*value); });
    }

    template <typename T>
    void number(const char* key, const T& value, T, T) {
        (*current_)[key] = valueJson(value);
    }

    void vec3(const char* key, const Vec3f& value, float, float) { (*current_)[key] = vec3Json(value); }

    void optionalVec3(const char* key, const std::optional<Vec3f>& value, float, float) {
        (*current_)[key] = value ? vec3Json(*value) : json(nullptr);
    }

    template <typename T, size_t N>
    void optionalArray(const char* key, const std::optional<std::array<T, N>>& value, T, T) {
        json& out = (*current_)[key] = nullptr;
        if (!value) return;
        out = json::array();
        for (T x : *value) out.push_back(valueJson(x));
    }

    void text(const char* key, const std::string& value) { (*current_)[key] = value; }
    void boolean(const char* key, bool value) { (*current_)[key] = value; }
    void choice(const char* key, const std::string& value, std::span<const char* const>) { (*current_)[key] = value; }

    void choiceList(const char* key, const std::vector<std::string>& value, std::span<const char* const>) {
        (*current_)[key] = value;
    }

    template <typename E, typename Names>
    void enumeration(const char* key, const E& value, const Names& names) {
        for (const auto& [name, e] : names)
            if (e == value) (*current_)[key] = name;
    }

    void colourMap(const char* key, const std::map<std::string, Vec3f>& value) {
        json& out = (*current_)[key] = json::object();
        for (const auto& [type, colour] : value) out[type] = vec3Json(colour);
    }

    void animation(const char* key, const AnimationDescription& value) { (*current_)[key] = animationToJson(value); }

private:
    template <typename T>
    static json valueJson(T value) {
        if constexpr (std::is_same_v<T, float>) return floatJson(value);
        else return value;
    }
    static json vec3Json(Vec3f v) { return {floatJson(v.x), floatJson(v.y), floatJson(v.z)}; }

    json* current_ = &root;
};

/// The end of the JSON string that opens at text[i] (its closing quote).
size_t stringEnd(const std::string& text, size_t i) {
    for (++i; i < text.size() && text[i] != '"'; ++i)
        if (text[i] == '\\') ++i;
    return i;
}

/// `text` (JSON as dump(2) writes it) with each array that holds no object or array on one line:
/// [0.1, 0.11, 0.09] rather than a number a line.
std::string withFlatArrays(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '"') {  // a string whole: brackets in it are text
            const size_t end = stringEnd(text, i);
            out.append(text, i, end - i + 1);
            i = end;
            continue;
        }
        size_t end = i + 1;
        if (text[i] == '[')
            for (; end < text.size() && !std::strchr("[]{}", text[end]); ++end)
                if (text[end] == '"') end = stringEnd(text, end);
        if (text[i] != '[' || end >= text.size() || text[end] != ']') {
            out += text[i];
            continue;
        }
        out += '[';
        for (size_t k = i + 1; k < end; ++k) {
            if (text[k] == '"') {
                const size_t close = stringEnd(text, k);
                out.append(text, k, close - k + 1);
                k = close;
            } else if (text[k] == ',') {
                out += ", ";
            } else if (text[k] != ' ' && text[k] != '\n') {
                out += text[k];
            }
        }
        out += ']';
        i = end;
    }
    return out;
}

} // namespace

json floatJson(float value) {
    const std::string text = numberText(value);
    const double shortest = std::strtod(text.c_str(), nullptr);
    return float(shortest) == value ? shortest : double(value);
}

std::string sceneFileText(const SceneDescription& description) {
    return withFlatArrays(sceneToJson(description).dump(2)) + "\n";
}

SceneDescription sceneFromJson(const json& json, const std::string& file) {
    SceneDescription d;
    FieldReader reader(json, file);
    visitSceneFields(d, reader);
    reader.finish();
    if (std::optional<SceneProblem> problem = firstSceneProblem(d))
        throw InputError(file + ": " + problem->key + ": " + problem->message);
    return d;
}

json sceneToJson(const SceneDescription& description) {
    FieldWriter writer;
    visitSceneFields(description, writer);
    return writer.root;
}

nlohmann::ordered_json readJsonFile(const std::string& path, const std::string& what) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path + ": cannot open the " + what + " (" + std::strerror(errno) + ")");
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw InputError(path + ": cannot read the " + what + " (a folder)");
    std::stringstream text;
    text << in.rdbuf();
    if (in.bad()) throw InputError(path + ": cannot read the " + what);
    try {
        return json::parse(text.str());
    } catch (const json::parse_error& e) {
        // "[json.exception.parse_error.101] parse error at line 2, column 5: ...": the part from "at line".
        std::string why = e.what();
        const size_t at = why.find(" at line ");
        why = at == std::string::npos ? why : why.substr(at + 1);
        for (char& c : why)
            if (c == '\n' || c == '\r') c = ' ';
        throw InputError(path + ": malformed JSON " + why);
    }
}

SceneDescription readSceneFile(const std::string& path) {
    const json parsed = readJsonFile(path, "scene file");
    SceneDescription d = sceneFromJson(parsed, path);
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    for (std::string* file : {&d.source.osm, &d.terrain.dem}) {
        const std::filesystem::path p(*file);
        if (!p.empty() && p.is_relative() && !folder.empty()) *file = (folder / p).lexically_normal().string();
    }
    return d;
}

void writeSceneFile(const SceneDescription& description, const std::string& path) {
    SceneDescription d = description;
    for (std::string* file : {&d.source.osm, &d.terrain.dem}) {
        const std::filesystem::path p(*file);
        if (p.empty() || !p.is_relative()) continue;
        std::error_code ec;
        const std::filesystem::path folder = std::filesystem::absolute(std::filesystem::path(path)).parent_path();
        const std::filesystem::path relative = std::filesystem::proximate(std::filesystem::absolute(p), folder, ec);
        if (!ec) *file = relative.string();
    }
    writeTextFileAtomically(path, sceneFileText(d));
}

} // namespace urbis
