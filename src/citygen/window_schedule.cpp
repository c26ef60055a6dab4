#include "citygen/window_schedule.h"

#include <algorithm>
#include <cmath>

namespace urbis {

namespace {

/// One share per hour 0, 1, ..., 23 (hour 24 is hour 0 again).
using DayTable = float[24];

//                                 0     1     2     3     4     5     6     7     8     9    10    11
//                                12    13    14    15    16    17    18    19    20    21    22    23
constexpr DayTable kResidential = {0.20f, 0.12f, 0.07f, 0.05f, 0.05f, 0.07f, 0.18f, 0.30f, 0.15f, 0.06f, 0.05f, 0.05f,
                                   0.05f, 0.05f, 0.05f, 0.06f, 0.10f, 0.25f, 0.45f, 0.60f, 0.65f, 0.60f, 0.45f, 0.30f};
constexpr DayTable kOffice = {0.04f, 0.03f, 0.03f, 0.03f, 0.03f, 0.03f, 0.06f, 0.20f, 0.55f, 0.70f, 0.70f, 0.70f,
                              0.65f, 0.70f, 0.70f, 0.70f, 0.70f, 0.60f, 0.40f, 0.25f, 0.12f, 0.08f, 0.06f, 0.05f};
constexpr DayTable kShop = {0.02f, 0.02f, 0.02f, 0.02f, 0.02f, 0.02f, 0.02f, 0.05f, 0.30f, 0.80f, 0.85f, 0.85f,
                            0.85f, 0.85f, 0.85f, 0.85f, 0.85f, 0.85f, 0.85f, 0.70f, 0.40f, 0.10f, 0.04f, 0.02f};
constexpr DayTable kShopWindow = {0.50f, 0.50f, 0.50f, 0.50f, 0.50f, 0.50f, 0.50f, 0.55f, 0.70f, 0.90f, 0.90f, 0.90f,
                                  0.90f, 0.90f, 0.90f, 0.90f, 0.90f, 0.90f, 0.90f, 0.90f, 0.85f, 0.75f, 0.65f, 0.55f};

float interpolate(const DayTable& table, float hour) {
    const float h = std::fmod(std::fmod(hour, 24.0f) + 24.0f, 24.0f);
    const int i = std::min(23, int(h));
    const float t = h - float(i);
    return table[i] + (table[(i + 1) % 24] - table[i]) * t;
}

} // namespace

WindowUse windowUseOf(BuildingType type) {
    switch (type) {
    case BuildingType::Residential:
    case BuildingType::House:
    case BuildingType::Apartments:
    case BuildingType::Hotel: return WindowUse::Residential;
    case BuildingType::Office:
    case BuildingType::Commercial:
    case BuildingType::Civic:
    case BuildingType::School:
    case BuildingType::Industrial:
    case BuildingType::Warehouse: return WindowUse::Office;
    case BuildingType::Retail: return WindowUse::Shop;
    case BuildingType::Generic:
    case BuildingType::Religious:
    case BuildingType::Hospital:
    case BuildingType::Garage:
    case BuildingType::Shed:
    case BuildingType::Roof: break;
    }
    return WindowUse::Mixed;
}

float litRoomShare(WindowUse use, float hour) {
    switch (use) {
    case WindowUse::Residential: return interpolate(kResidential, hour);
    case WindowUse::Office: return interpolate(kOffice, hour);
    case WindowUse::Shop: return interpolate(kShop, hour);
    case WindowUse::Mixed: break;
    }
    return 0.5f * (interpolate(kResidential, hour) + interpolate(kOffice, hour));
}

float litShopWindowShare(float hour) { return interpolate(kShopWindow, hour); }

uint8_t chanceByte(float share) { return uint8_t(std::lround(std::clamp(share, 0.0f, 1.0f) * 255.0f)); }

} // namespace urbis
