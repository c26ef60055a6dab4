#include "streets/marking_rules.h"

#include "scene/road_segment.h"

#include <algorithm>

namespace urbis {

namespace {

/// Whether road paint is laid on a surface: asphalt, concrete and (rarely, but mapped) paving stones.
bool takesPaint(RoadSurface surface) {
    switch (surface) {
    case RoadSurface::Asphalt:
    case RoadSurface::Concrete:
    case RoadSurface::PavingStones:
    case RoadSurface::Unknown: return true;   // the class's default: asphalt on every marked class
    default: return false;
    }
}

} // namespace

bool isPaved(RoadSurface surface) {
    switch (surface) {
    case RoadSurface::Gravel:
    case RoadSurface::Dirt:
    case RoadSurface::Grass: return false;
    default: return true;
    }
}

uint32_t markingBits(const Road& road, bool american) {
    switch (road.highway) {
    case HighwayClass::Motorway:
    case HighwayClass::Trunk:
    case HighwayClass::Primary:
    case HighwayClass::Secondary:
    case HighwayClass::Tertiary:
    case HighwayClass::Unclassified:
    case HighwayClass::Residential: break;
    default: return 0;
    }
    if (!road.laneMarkings || !takesPaint(road.surface)) return 0;
    const bool highway = road.highway == HighwayClass::Motorway || road.highway == HighwayClass::Trunk;
    // Lanes each way: as tagged, else half the lanes (the larger half forward).
    const int forward = road.oneway ? road.lanes : road.lanesForward > 0 ? road.lanesForward : (road.lanes + 1) / 2;
    const int backward = road.oneway ? 0 : road.lanesBackward > 0 ? road.lanesBackward : road.lanes / 2;
    uint32_t bits = 0;
    if (!road.oneway && road.lanes >= 2 && road.width >= kCentreLineMinWidth) {
        bits |= kMarkCentreLine;
        // No overtaking across a multi-lane road's centre line (RMS, MUTCD 3B.01) nor on a trunk.
        if (road.overtaking && !highway && std::max(forward, backward) < 2) bits |= kMarkCentreDashed;
        if (american) bits |= kMarkCentreYellow;
    }
    if (std::max(forward, backward) >= 2) bits |= kMarkLaneDividers;
    if (highway) bits |= kMarkEdgeLines;
    return bits != 0 && american ? bits | kMarkAmerican : bits;
}

} // namespace urbis
