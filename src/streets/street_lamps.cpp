#include "streets/street_lamps.h"

#include "streets/lamp_mesher.h"
#include "streets/street_materials.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>
#include <string_view>

namespace urbis {

static_assert(uint32_t(StreetMaterial::LampHousing) == uint32_t(StreetMaterial::LampMetal) + uint32_t(LampMaterial::Housing) &&
                  uint32_t(StreetMaterial::LampGlass) == uint32_t(StreetMaterial::LampMetal) + uint32_t(LampMaterial::Glass),
              "LampMaterial indexes the street materials from LampMetal");
static_assert(uint8_t(LampHead::Flat) == uint8_t(LampShape::Flat), "LampShape follows LampHead");

LampLight lampLightOf(const std::string& lampType) {
    std::string type(lampType);
    std::transform(type.begin(), type.end(), type.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    const auto has = [&](std::string_view word) { return type.find(word) != std::string::npos; };
    if (has("low_pressure")) return {1800.0f, 10000.0f};
    if (has("sodium")) return {2000.0f, 15000.0f};
    if (has("mercury")) return {4100.0f, 6000.0f};
    if (has("halide")) return {4200.0f, 12000.0f};
    if (has("fluorescent")) return {4000.0f, 3000.0f};
    if (has("incandescent") || has("halogen")) return {2700.0f, 1500.0f};
    if (has("gas")) return {2200.0f, 1000.0f};
    return {4000.0f, 8000.0f};
}

LampRecord lampRecordOf(const Lamp& lamp, uint32_t object, uint32_t firstMaterial) {
    LampRecord r;
    const float h = lamp.height;
    r.base = {float(lamp.position.x), 0.0f, float(-lamp.position.y)};
    r.height = h;
    const double bearing = (lamp.direction < 0.0f ? 90.0 : double(lamp.direction)) * std::numbers::pi / 180.0;
    r.armX = float(std::sin(bearing));
    r.armZ = float(-std::cos(bearing));
    r.shape = LampShape(lamp.head);
    const bool onPole = lamp.mount != LampMount::Wall && lamp.mount != LampMount::Suspended;
    r.poleRadius = onPole ? std::clamp(0.012f * h, 0.05f, 0.12f) : 0.0f;
    const bool armHead = r.shape == LampShape::Cobra || r.shape == LampShape::Flat;
    switch (lamp.mount) {
    case LampMount::BentMast: r.armLength = std::clamp(0.25f * h, 1.0f, 3.0f); break;
    case LampMount::Pole: r.armLength = armHead ? std::clamp(0.15f * h, 0.6f, 2.0f) : 0.0f; break;
    case LampMount::Wall: r.armLength = 0.6f; break;
    default: r.armLength = 0.0f;
    }
    const float base = r.shape == LampShape::Cobra || r.shape == LampShape::Flat ? 0.6f
                       : r.shape == LampShape::Globe                               ? 0.45f
                                                                                   : 0.5f;
    r.headSize = base * std::clamp(0.5f + h / 16.0f, 0.7f, 1.3f);
    r.object = object;
    r.material = firstMaterial + uint32_t(StreetMaterial::LampMetal);
    const LampLight light = lampLightOf(lamp.lampType);
    r.colourTemperature = lamp.colourTemperature > 0.0f ? lamp.colourTemperature : light.colourTemperature;
    r.luminousFlux = light.luminousFlux * float(std::max(1, lamp.lightCount));
    return r;
}

void addLamps(const std::vector<Lamp>& lamps, const StreetOptions& options, StreetMesh& out) {
    uint64_t made = 0;
    size_t triangles = 0;
    for (const Lamp& lamp : lamps) {
        if (!std::isfinite(lamp.position.x) || !std::isfinite(lamp.position.y) || !std::isfinite(lamp.height) ||
            !(lamp.height > 0.0f)) {
            ++out.dropped["lamp_bad_geometry"];
            continue;
        }
        const LampRecord record = lampRecordOf(lamp, options.firstObject + out.objects++, options.firstMaterial);
        if (options.lamps == Representation::Procedural) out.lamps.push_back(record);
        else triangles += meshLamp(record, out.mesh);
        ++made;
    }
    out.counts["lamps"] += made;
    if (options.lamps != Representation::Procedural) out.trianglesByKind["lamps"] += triangles;
}

} // namespace urbis
