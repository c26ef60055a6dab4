// Which part of an object a surface is: the same tag for a procedural wall's cell part and the
// twin's triangle made from it, so an ID buffer can compare the two representations.
#pragma once

#include <cstdint>

namespace urbis {

enum class SurfacePart : uint8_t {
    Whole,        ///< the ground, or anything not split into parts
    Roof,
    Facade,       ///< the wall's outer plane: margins, plain walls and the frame around openings
    Jamb,         ///< the sides, sill and lintel of a recessed opening
    Glass,
    Room,         ///< back, sides, floor and ceiling of the room behind a window
    BalconySlab,
    Railing,
    Mullion,      ///< the frame of a curtain wall
    Spandrel,     ///< the opaque panel between two floors of a curtain wall
    Road,         ///< a carriageway; its triangles' object is a RoadSegment (markings are a function of the hit)
    Junction,     ///< the polygon where three or more roads meet
    Sidewalk,     ///< a sidewalk's top, a footway, a paved area
    Curb,         ///< the curb's face between a carriageway and its sidewalk
    GroundCover,  ///< landuse, leisure and natural areas over the ground
    Water,
    BridgeDeck,   ///< a bridge's sides and underside (its top is Road or Sidewalk)
    Parapet,
    Pier,
    Ballast,
    Rail,
    LampPole,     ///< a street lamp's pole and arm
    LampHead,
    LampGlass,    ///< the lamp's emitting glass
    TreeTrunk,    ///< a tree's trunk and branches
    TreeCrown,    ///< a tree's leaves or needles
    Count
};

/// Bits of a surface ID taken by the part.
inline constexpr uint32_t kSurfacePartBits = 5;
static_assert(uint32_t(SurfacePart::Count) <= (1u << kSurfacePartBits), "parts must fit their bits");

} // namespace urbis
