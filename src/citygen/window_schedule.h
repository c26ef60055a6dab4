// Which rooms are lit at an hour, by the building's use (host, pure): the share of lit rooms that a
// wall's cells draw against (WallRecord::litChance, shopLitChance; geometry/wall_parts.h). The
// table is in docs/facades.md § Lit windows.
#pragma once

#include "model/city_model.h"

#include <cstdint>

namespace urbis {

/// How a building's rooms are lit through the day.
enum class WindowUse : uint8_t {
    Residential,  ///< homes and hotels: lit in the evening, few at deep night, few by day
    Office,       ///< offices, commerce, civic buildings, schools, industry: lit in working hours, dark after
    Shop,         ///< retail: lit in opening hours
    Mixed         ///< untyped and other buildings: between homes and offices
};

/// The use of a building of `type`.
WindowUse windowUseOf(BuildingType type);

/// Share of lit rooms of `use` at local clock `hour` (0 to 24, wraps), interpolated linearly between
/// the table's hours.
float litRoomShare(WindowUse use, float hour);

/// Share of lit shop windows (a shop-front wall's ground floor) at `hour`: most in opening hours, and
/// many at night too (shop windows stay lit for display).
float litShopWindowShare(float hour);

/// A share as WallRecord's chance in 255ths.
uint8_t chanceByte(float share);

} // namespace urbis
