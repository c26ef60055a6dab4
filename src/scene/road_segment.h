// A straight piece of a carriageway as markings see it (host+device POD): where it lies, how wide it
// is, its lanes and which lines are painted on it. Nothing is stored per stripe: a road triangle's
// hit finds its segment (its TriangleInfo::object) and the markings are a function of the hit's
// distance along and across it (streets/ fills the records; geometry/ paints them).
#pragma once

#include "math/vec.h"

#include <cstdint>

namespace urbis {

/// Which lines a segment carries (bits of RoadSegment::markings).
enum RoadMarking : uint32_t {
    kMarkCentreLine = 1u << 0,    ///< a line between the two directions
    kMarkCentreDashed = 1u << 1,  ///< ... dashed (overtaking allowed), else solid
    kMarkCentreYellow = 1u << 2,  ///< ... yellow (the Americas), else white
    kMarkLaneDividers = 1u << 3,  ///< dashed lines between lanes of one direction
    kMarkEdgeLines = 1u << 4,     ///< solid lines along both edges
    kMarkStopAtStart = 1u << 5,   ///< a stop line across the lanes that arrive at the segment's start
    kMarkStopAtEnd = 1u << 6,     ///< ... at its end
    kMarkZebraAtStart = 1u << 7,  ///< zebra stripes of a crossing centred on the segment's start
    kMarkZebraAtEnd = 1u << 8,    ///< ... on its end
    kMarkAmerican = 1u << 9,      ///< the MUTCD's layout: 3 m / 9 m dashes, a solid centre line doubled
    kMarkLeftHand = 1u << 10,     ///< traffic keeps left: the forward lanes lie left of the centre line
};

struct RoadSegment {
    Vec2f start;              ///< world (x, z) of the centreline where the segment starts, metres
    Vec2f direction;          ///< unit, world (x, z), along the road
    float length = 0;         ///< m, of this segment
    float distance = 0;       ///< m along the road's centreline at `start`: dashes run on across segments
    float halfWidth = 0;      ///< m, half the carriageway
    float centreOffset = 0;   ///< m across (left of `direction` positive) of the line between the directions
    uint8_t lanesForward = 1; ///< lanes in `direction`, right of the centre line (left with kMarkLeftHand)
    uint8_t lanesBackward = 1;///< lanes against it, on the other side; 0 on a one-way road (centreOffset = halfWidth,
                              ///< -halfWidth with kMarkLeftHand)
    uint16_t spare = 0;
    uint32_t markings = 0;    ///< RoadMarking bits
    uint32_t object = 0;      ///< the road's object id (ID AOV)
    uint32_t paint = 0;       ///< material of white paint; paint + 1 is yellow
};

static_assert(sizeof(RoadSegment) == 48, "RoadSegment is meant to be 48 bytes");

} // namespace urbis
