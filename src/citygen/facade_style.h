// Facade parameters of a building from its tags and seed: a pure, table-driven step, tested
// apart from geometry (host).
#pragma once

#include "scene/wall_record.h"
#include "model/city_model.h"

namespace urbis {

/// What every wall of one building shares. Lengths in metres.
struct FacadeStyle {
    bool hasFacade = true;          ///< false: the building's walls stay plain (sheds, garages, roofs)
    WallStyle style = WallStyle::Punched;
    uint8_t flags = 0;              ///< WallFlags
    float floorHeight = 3.2f;       ///< storey height when building:levels is unknown
    float slotWidth = 3.0f;         ///< target width of a slot (the walls round it to fit)
    float windowFraction = 0.5f;    ///< window width / slot width
    float windowHeight = 1.5f;
    float sillHeight = 0.9f;        ///< punched: window bottom above the floor; curtain: spandrel height
    float reveal = 0.2f;            ///< depth of the glass behind the wall plane
    float roomDepth = 3.0f;
    float balconyDepth = 1.2f;      ///< used where flags has kWallBalconies
};

/// The facade style of `building`, from its type, material and levels, varied by its seed: glazed
/// curtain walls on glass office and commercial towers, shop windows on retail and commercial
/// ground floors, balconies on some homes, apartment blocks and hotels (never elsewhere), high
/// windows on sheds and halls.
FacadeStyle facadeStyleOf(const Building& building);

} // namespace urbis
