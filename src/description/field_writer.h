// Writes a description into a scene file's JSON by walking visitSceneFields (description/
// scene_fields.h): every key, null for the optional ones left unset.
#pragma once

#include "description/animation_json.h"
#include "base/choice.h"
#include "description/scene_field.h"
#include "description/scene_json.h"
#include "math/vec.h"

#include <nlohmann/json.hpp>

#include <array>
#include <map>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace urbis {

/// Writes every field into a JSON object tree, following visitSceneFields.
class FieldWriter {
public:
    using json = nlohmann::ordered_json;

    json root = json::object();

    template <typename F>
    void object(const char* key, F&& fields) {
        json* outer = current_;
        current_ = &((*outer)[key] = json::object());
        fields();
        current_ = outer;
    }

    template <typename T, typename F>
    void optionalObject(const Field& f, const std::optional<T>& value, F&& fields) {
        if (!value) {
            (*current_)[f.key] = nullptr;
            return;
        }
        object(f.key, [&] { fields(*value); });
    }

    template <typename T>
    void number(const Field& f, const T& value, T, T) {
        (*current_)[f.key] = valueJson(value);
    }

    void vec3(const Field& f, const Vec3f& value, float, float) { (*current_)[f.key] = vec3Json(value); }

    void optionalVec3(const Field& f, const std::optional<Vec3f>& value, float, float) {
        (*current_)[f.key] = value ? vec3Json(*value) : json(nullptr);
    }

    template <typename T, size_t N>
    void optionalArray(const Field& f, const std::optional<std::array<T, N>>& value, T, T) {
        json& out = (*current_)[f.key] = nullptr;
        if (!value) return;
        out = json::array();
        for (T x : *value) out.push_back(valueJson(x));
    }

    void text(const Field& f, const std::string& value) { (*current_)[f.key] = value; }
    void boolean(const Field& f, bool value) { (*current_)[f.key] = value; }

    template <typename Table>
    void choice(const Field& f, const std::string& value, const Table&) {
        (*current_)[f.key] = value;
    }

    template <typename Table>
    void choiceList(const Field& f, const std::vector<std::string>& value, const Table&) {
        (*current_)[f.key] = value;
    }

    template <typename E, size_t N>
    void enumeration(const Field& f, const E& value, const Choice<E> (&table)[N]) {
        (*current_)[f.key] = nameOfChoice(table, value);
    }

    void colourMap(const Field& f, const std::map<std::string, Vec3f>& value) {
        json& out = (*current_)[f.key] = json::object();
        for (const auto& [type, colour] : value) out[type] = vec3Json(colour);
    }

    template <typename Keyframe>
    void keyframes(const Field& f, const std::vector<Keyframe>& value) {
        (*current_)[f.key] = keyframesToJson(value);
    }

private:
    template <typename T>
    static json valueJson(T value) {
        if constexpr (std::is_same_v<T, float>) return floatJson(value);
        else return value;
    }
    static json vec3Json(Vec3f v) { return {floatJson(v.x), floatJson(v.y), floatJson(v.z)}; }

    json* current_ = &root;
};

} // namespace urbis
