#include "app/view_panel.h"

#include "astro/civil_time.h"
#include "description/scene_fields.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace urbis {

namespace {

template <typename T>
constexpr ImGuiDataType dataTypeOf() {
    if constexpr (std::is_same_v<T, float>) return ImGuiDataType_Float;
    else if constexpr (std::is_same_v<T, double>) return ImGuiDataType_Double;
    else if constexpr (std::is_same_v<T, uint32_t>) return ImGuiDataType_U32;
    else if constexpr (std::is_same_v<T, uint64_t>) return ImGuiDataType_U64;
    else static_assert(sizeof(T) == 0, "a scene field of a type the panel does not know");
}

/// A drag's step per pixel: a thousandth of a narrow range, a hundredth of the value in a wide one.
template <typename T>
float dragSpeed(T value, T lo, T hi) {
    const double span = double(hi) - double(lo);
    if (span <= 1000.0) return float(std::max(span / 1000.0, std::is_integral_v<T> ? 0.05 : 1e-4));
    return float(std::max(std::abs(double(value)) * 0.01, std::is_integral_v<T> ? 0.2 : 0.01));
}

/// Makes ImGui widgets of visitSceneFields' fields (scene_fields.h lists the calls), noting edits.
class PanelVisitor {
public:
    PanelEdit edit;

    template <typename F>
    void object(const char* key, F&& fields) {
        if (ImGui::TreeNode(key)) {
            fields();
            ImGui::TreePop();
        }
    }

    template <typename T, typename F>
    void optionalObject(const char* key, std::optional<T>& value, F&& fields) {
        optional(key, value, [&](T& v) { object(key, [&] { fields(v); }); });
    }

    template <typename T>
    void number(const char* key, T& value, std::type_identity_t<T> lo, std::type_identity_t<T> hi) {
        dragged(ImGui::DragScalar(key, dataTypeOf<T>(), &value, dragSpeed(value, lo, hi), &lo, &hi, nullptr,
                                  ImGuiSliderFlags_AlwaysClamp));
    }

    void vec3(const char* key, Vec3f& value, float, float hi) {
        const ImGuiColorEditFlags flags = ImGuiColorEditFlags_Float | (hi > 1.0f ? ImGuiColorEditFlags_HDR : 0);
        dragged(ImGui::ColorEdit3(key, &value.x, flags));
    }

    void optionalVec3(const char* key, std::optional<Vec3f>& value, float lo, float hi) {
        optional(key, value, [&](Vec3f& v) { dragged(ImGui::DragFloat3(key, &v.x, dragSpeed(v.x, lo, hi), lo, hi)); });
    }

    template <typename T, size_t N>
    void optionalArray(const char* key, std::optional<std::array<T, N>>& value, T lo, T hi) {
        optional(key, value, [&](std::array<T, N>& a) {
            dragged(ImGui::DragScalarN(key, dataTypeOf<T>(), a.data(), int(N), dragSpeed(a[0], lo, hi), &lo, &hi));
        });
    }

    void text(const char* key, std::string& value) {
        discrete(ImGui::InputText(key, &value, ImGuiInputTextFlags_EnterReturnsTrue));
    }

    void boolean(const char* key, bool& value) { discrete(ImGui::Checkbox(key, &value)); }

    void choice(const char* key, std::string& value, std::span<const char* const> names) {
        if (!ImGui::BeginCombo(key, value.c_str())) return;
        for (const char* name : names)
            if (discrete(ImGui::Selectable(name, value == name))) value = name;
        ImGui::EndCombo();
    }

    void choiceList(const char* key, std::vector<std::string>& value, std::span<const char* const> names) {
        if (!ImGui::TreeNode(key)) return;
        std::vector<std::string> chosen;
        for (const char* name : names) {
            bool on = std::find(value.begin(), value.end(), name) != value.end();
            discrete(ImGui::Checkbox(name, &on));
            if (on) chosen.emplace_back(name);
        }
        value = std::move(chosen);
        ImGui::TreePop();
    }

    template <typename E, typename Names>
    void enumeration(const char* key, E& value, const Names& names) {
        const char* shown = "";
        for (const auto& [name, e] : names)
            if (e == value) shown = name;
        if (!ImGui::BeginCombo(key, shown)) return;
        for (const auto& [name, e] : names)
            if (discrete(ImGui::Selectable(name, e == value))) value = e;
        ImGui::EndCombo();
    }

    void colourMap(const char* key, std::map<std::string, Vec3f>& value) {
        if (!ImGui::TreeNode(key)) return;
        if (value.empty()) ImGui::TextDisabled("(none: the palettes' colours)");
        for (auto& [type, colour] : value) vec3(type.c_str(), colour, 0.0f, 1.0f);
        ImGui::TreePop();
    }

    /// Keyframes are edited in the scene file (docs/animation.md); the panel says how many there are.
    void animation(const char* key, const AnimationDescription& value) {
        ImGui::TextDisabled("%s: %zu camera and %zu time keyframes", key, value.camera.size(), value.time.size());
    }

private:
    bool discrete(bool edited) {
        edit.changed |= edited;
        edit.committed |= edited;
        return edited;
    }
    void dragged(bool edited) {
        edit.changed |= edited;
        edit.committed |= ImGui::IsItemDeactivatedAfterEdit();
    }
    template <typename T, typename F>
    void optional(const char* key, std::optional<T>& value, F&& widget) {
        bool set = value.has_value();
        if (discrete(ImGui::Checkbox(("##set " + std::string(key)).c_str(), &set))) {
            if (set) value = T{};
            else value.reset();
        }
        ImGui::SameLine();
        if (value) widget(*value);
        else ImGui::TextDisabled("%s (unset)", key);
    }
};

} // namespace

PanelEdit drawScenePanel(SceneDescription& scene) {
    PanelVisitor visitor;
    visitSceneFields(scene, visitor);
    return visitor.edit;
}

PanelEdit drawTimeOfDay(SceneDescription& scene, std::array<double, 2> location) {
    PanelEdit edit;
    std::string error;
    std::optional<CivilTime> time = scene.astronomy.time.empty() ? std::nullopt : parseIsoTime(scene.astronomy.time, error);
    bool on = time.has_value();
    if (ImGui::Checkbox("date and time", &on)) {
        edit.changed = edit.committed = true;
        if (on) {
            CivilTime noon{2024, 6, 21, 12, 0, 0, int(std::lround(location[0] / 15.0)) * 60};
            scene.astronomy.time = formatIsoTime(noon);
            scene.astronomy.sunFromTime = true;
        } else {
            scene.astronomy.time.clear();
        }
        return edit;
    }
    if (!time) return edit;
    int date[3] = {time->year, time->month, time->day};
    float hours = float(time->hour) + float(time->minute) / 60.0f;
    bool changed = ImGui::InputInt3("date", date, ImGuiInputTextFlags_EnterReturnsTrue);
    const bool committed = changed;
    changed |= ImGui::SliderFloat("local hour", &hours, 0.0f, 23.99f, "%.2f h");
    edit.committed = committed || ImGui::IsItemDeactivatedAfterEdit();
    if (!changed) return edit;
    edit.changed = true;
    CivilTime next = *time;
    next.year = std::clamp(date[0], 1583, 9999);
    next.month = std::clamp(date[1], 1, 12);
    next.day = std::clamp(date[2], 1, daysInMonth(next.year, next.month));
    const int minutes = std::clamp(int(std::lround(hours * 60.0f)), 0, 24 * 60 - 1);
    next.hour = minutes / 60;
    next.minute = minutes % 60;
    next.second = 0;
    scene.astronomy.time = formatIsoTime(next);
    return edit;
}

} // namespace urbis
