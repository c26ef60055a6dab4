#include "citygen/lit_room_palette.h"

#include <algorithm>
#include <cmath>

namespace urbis {

namespace {

/// The nearest of `levels` steps from `lo` to `hi` to `x`.
uint32_t nearestStep(float x, float lo, float hi, uint32_t levels) {
    const float step = (x - lo) / (hi - lo) * float(levels - 1);
    return uint32_t(std::clamp(std::lround(step), 0l, long(levels - 1)));
}

} // namespace

uint32_t litRoomPaletteEntry(const WindowLook& look) {
    const uint32_t colour = nearestStep(look.coolness, 0.0f, 1.0f, kLitRoomColours);
    const uint32_t level = nearestStep(windowMeanIntensity(look), kLitRoomLevelLow, kLitRoomLevelHigh, kLitRoomLevels);
    return level * kLitRoomColours + colour;
}

float litRoomEntryCoolness(uint32_t entry) { return float(entry % kLitRoomColours) / float(kLitRoomColours - 1); }

float litRoomEntryIntensity(uint32_t entry) {
    return kLitRoomLevelLow + (kLitRoomLevelHigh - kLitRoomLevelLow) * float(entry / kLitRoomColours) / float(kLitRoomLevels - 1);
}

std::vector<Material> litRoomPaletteMaterials(const Material& litRoom) {
    std::vector<Material> out;
    for (uint32_t entry = 0; entry < kLitRoomPaletteSize; ++entry) {
        Material m = litRoom;
        m.emission = windowColour(litRoomEntryCoolness(entry)) * (luminance(litRoom.emission) * litRoomEntryIntensity(entry));
        out.push_back(m);
    }
    return out;
}

} // namespace urbis
