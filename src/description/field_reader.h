// Reads a scene file's JSON into a description by walking visitSceneFields (description/
// scene_fields.h): every problem one line naming the file and the key path, and a key that no field
// names is unknown.
#pragma once

#include "description/animation_json.h"
#include "description/building_type_names.h"
#include "base/choice.h"
#include "description/scene_field.h"
#include "base/input_error.h"
#include "math/vec.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <charconv>
#include <map>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace urbis {

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
    using json = nlohmann::ordered_json;

    /// Reads `root`, the object at `path` of `file` (empty: the whole file).
    FieldReader(const json& root, const std::string& file, const std::string& path = "") : file_(file) {
        if (!root.is_object()) {
            if (path.empty()) throw InputError(file_ + ": expected a JSON object of the sections source, camera, ...");
            throw InputError(file_ + ": " + path + ": expected an object");
        }
        frames_.push_back({&root, path, {}});
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
    void optionalObject(const Field& f, std::optional<T>& value, F&& fields) {
        const json* node = child(f.key);
        if (!node) return;
        if (node->is_null()) {
            value.reset();
            return;
        }
        if (!node->is_object()) fail(f.key, "expected an object or null");
        value = T{};
        enter(f.key, *node);
        fields(*value);
        leave();
    }

    template <typename T>
    void number(const Field& f, T& value, std::type_identity_t<T> lo, std::type_identity_t<T> hi) {
        if (const json* node = child(f.key)) value = numberIn(*node, f.key, lo, hi);
    }

    void vec3(const Field& f, Vec3f& value, float lo, float hi) {
        if (const json* node = child(f.key)) value = vec3In(*node, f.key, lo, hi, "expected an array of 3 numbers");
    }

    void optionalVec3(const Field& f, std::optional<Vec3f>& value, float lo, float hi) {
        const json* node = child(f.key);
        if (!node) return;
        if (node->is_null()) value.reset();
        else value = vec3In(*node, f.key, lo, hi, "expected null or an array of 3 numbers");
    }

    template <typename T, size_t N>
    void optionalArray(const Field& f, std::optional<std::array<T, N>>& value, T lo, T hi) {
        const json* node = child(f.key);
        if (!node) return;
        if (node->is_null()) {
            value.reset();
            return;
        }
        if (!node->is_array() || node->size() != N) fail(f.key, "expected null or an array of " + std::to_string(N) + " numbers");
        std::array<T, N> a{};
        for (size_t i = 0; i < N; ++i) a[i] = numberIn((*node)[i], f.key + ("[" + std::to_string(i) + "]"), lo, hi);
        value = a;
    }

    void text(const Field& f, std::string& value) {
        const json* node = child(f.key);
        if (!node) return;
        if (!node->is_string()) fail(f.key, "expected a string");
        value = node->get<std::string>();
    }

    void boolean(const Field& f, bool& value) {
        const json* node = child(f.key);
        if (!node) return;
        if (!node->is_boolean()) fail(f.key, "expected true or false");
        value = node->get<bool>();
    }

    template <typename Table>
    void choice(const Field& f, std::string& value, const Table& names) {
        const json* node = child(f.key);
        if (!node) return;
        for (const auto& entry : names)
            if (node->is_string() && node->get<std::string>() == choiceName(entry)) {
                value = choiceName(entry);
                return;
            }
        fail(f.key, "expected one of " + nameList(names));
    }

    template <typename Table>
    void choiceList(const Field& f, std::vector<std::string>& value, const Table& names) {
        const json* node = child(f.key);
        if (!node) return;
        const std::string list = nameList(names);
        if (!node->is_array()) fail(f.key, "expected an array of names out of " + list);
        std::vector<std::string> chosen;
        for (size_t i = 0; i < node->size(); ++i) {
            const json& item = (*node)[i];
            const std::string path = f.key + ("[" + std::to_string(i) + "]");
            const bool known = item.is_string() && std::any_of(std::begin(names), std::end(names), [&](const auto& entry) {
                                   return item.get<std::string>() == choiceName(entry);
                               });
            if (!known) fail(path, "expected one of " + list);
            if (std::find(chosen.begin(), chosen.end(), item.get<std::string>()) != chosen.end()) fail(path, "named twice");
            chosen.push_back(item.get<std::string>());
        }
        value = std::move(chosen);
    }

    template <typename E, size_t N>
    void enumeration(const Field& f, E& value, const Choice<E> (&table)[N]) {
        const json* node = child(f.key);
        if (!node) return;
        if (node->is_string())
            if (const std::optional<E> named = choiceNamed(table, node->get<std::string>())) {
                value = *named;
                return;
            }
        fail(f.key, "expected one of " + nameList(table));
    }

    void colourMap(const Field& f, std::map<std::string, Vec3f>& value) {
        const json* node = child(f.key);
        if (!node) return;
        if (!node->is_object()) fail(f.key, "expected an object of building type -> [r, g, b]");
        value.clear();
        for (const auto& [type, colour] : node->items()) {
            const std::string path = std::string(f.key) + "." + type;
            if (!buildingTypeNamed(type)) fail(path, "unknown building type (types: " + buildingTypeNameList() + ")");
            value[type] = vec3In(colour, path, 0.0f, 1.0f, "expected an array of 3 numbers");
        }
    }

    void keyframes(const Field& f, std::vector<CameraKeyframe>& value) {
        if (const json* node = child(f.key)) value = cameraKeyframesFromJson(*node, file_, pathOf(f.key));
    }

    void keyframes(const Field& f, std::vector<TimeKeyframe>& value) {
        if (const json* node = child(f.key)) value = timeKeyframesFromJson(*node, file_, pathOf(f.key));
    }

private:
    struct Frame {
        const json* node;
        std::string path;                 ///< of this object; empty at the top
        std::vector<std::string> known;   ///< the keys the fields named
    };

    template <typename Table>
    static std::string nameList(const Table& names) {
        std::string list;
        for (const auto& entry : names) list += (list.empty() ? "" : ", ") + std::string(choiceName(entry));
        return list;
    }

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

} // namespace urbis
