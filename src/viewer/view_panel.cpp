#include "viewer/view_panel.h"

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

/// Makes ImGui widgets of visitSceneFields' fields (scene_fields.h lists the calls), each labelled by
/// its key with its help as the tooltip, noting edits.
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
    void optionalObject(const Field& f, std::optional<T>& value, F&& fields) {
        optional(f, value, [&](T& v) { object(f.key, [&] { fields(v); }); });
    }

    template <typename T>
    void number(const Field& f, T& value, std::type_identity_t<T> lo, std::type_identity_t<T> hi) {
        dragged(f, ImGui::DragScalar(f.key, dataTypeOf<T>(), &value, dragSpeed(value, lo, hi), &lo, &hi, nullptr,
                                     ImGuiSliderFlags_AlwaysClamp));
    }

    void vec3(const Field& f, Vec3f& value, float, float hi) {
        const ImGuiColorEditFlags flags = ImGuiColorEditFlags_Float | (hi > 1.0f ? ImGuiColorEditFlags_HDR : 0);
        dragged(f, ImGui::ColorEdit3(f.key, &value.x, flags));
    }

    void optionalVec3(const Field& f, std::optional<Vec3f>& value, float lo, float hi) {
        optional(f, value, [&](Vec3f& v) { dragged(f, ImGui::DragFloat3(f.key, &v.x, dragSpeed(v.x, lo, hi), lo, hi)); });
    }

    template <typename T, size_t N>
    void optionalArray(const Field& f, std::optional<std::array<T, N>>& value, T lo, T hi) {
        optional(f, value, [&](std::array<T, N>& a) {
            dragged(f, ImGui::DragScalarN(f.key, dataTypeOf<T>(), a.data(), int(N), dragSpeed(a[0], lo, hi), &lo, &hi));
        });
    }

    void text(const Field& f, std::string& value) {
        discrete(f, ImGui::InputText(f.key, &value, ImGuiInputTextFlags_EnterReturnsTrue));
    }

    void boolean(const Field& f, bool& value) { discrete(f, ImGui::Checkbox(f.key, &value)); }

    template <typename Table>
    void choice(const Field& f, std::string& value, const Table& table) {
        const bool open = ImGui::BeginCombo(f.key, value.c_str());
        tooltip(f);
        if (!open) return;
        for (const auto& entry : table)
            if (discrete(f, ImGui::Selectable(choiceName(entry), value == choiceName(entry)))) value = choiceName(entry);
        ImGui::EndCombo();
    }

    template <typename Table>
    void choiceList(const Field& f, std::vector<std::string>& value, const Table& table) {
        const bool open = ImGui::TreeNode(f.key);
        tooltip(f);
        if (!open) return;
        std::vector<std::string> chosen;
        for (const auto& entry : table) {
            const char* name = choiceName(entry);
            bool on = std::find(value.begin(), value.end(), name) != value.end();
            discrete(f, ImGui::Checkbox(name, &on));
            if (on) chosen.emplace_back(name);
        }
        value = std::move(chosen);
        ImGui::TreePop();
    }

    template <typename E, size_t N>
    void enumeration(const Field& f, E& value, const Choice<E> (&table)[N]) {
        const bool open = ImGui::BeginCombo(f.key, nameOfChoice(table, value));
        tooltip(f);
        if (!open) return;
        for (const Choice<E>& entry : table)
            if (discrete(f, ImGui::Selectable(entry.name, entry.value == value))) value = entry.value;
        ImGui::EndCombo();
    }

    void colourMap(const Field& f, std::map<std::string, Vec3f>& value) {
        const bool open = ImGui::TreeNode(f.key);
        tooltip(f);
        if (!open) return;
        if (value.empty()) ImGui::TextDisabled("(none: the palettes' colours)");
        for (auto& [type, colour] : value) dragged(f, ImGui::ColorEdit3(type.c_str(), &colour.x, ImGuiColorEditFlags_Float));
        ImGui::TreePop();
    }

    /// Keyframes are edited in the scene file (docs/animation.md); the panel says how many there are.
    template <typename Keyframe>
    void keyframes(const Field& f, const std::vector<Keyframe>& value) {
        ImGui::TextDisabled("%s: %zu keyframes", f.key, value.size());
        tooltip(f);
    }

private:
    static void tooltip(const Field& f) {
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s (%s)", f.help, f.flag ? f.flag : "scene file only");
    }
    bool discrete(const Field& f, bool edited) {
        tooltip(f);
        edit.changed |= edited;
        edit.committed |= edited;
        return edited;
    }
    void dragged(const Field& f, bool edited) {
        tooltip(f);
        edit.changed |= edited;
        edit.committed |= ImGui::IsItemDeactivatedAfterEdit();
    }
    template <typename T, typename F>
    void optional(const Field& f, std::optional<T>& value, F&& widget) {
        bool set = value.has_value();
        if (discrete(f, ImGui::Checkbox(("##set " + std::string(f.key)).c_str(), &set))) {
            if (set) value = T{};
            else value.reset();
        }
        ImGui::SameLine();
        if (value) widget(*value);
        else ImGui::TextDisabled("%s (unset)", f.key);
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
