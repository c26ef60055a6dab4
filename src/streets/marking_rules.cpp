#include "streets/marking_rules.h"

#include "scene/road_segment.h"

namespace urbis {

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
    if (!road.laneMarkings || !isPaved(road.surface) || road.surface == RoadSurface::Sett ||
        road.surface == RoadSurface::Cobblestone)
        return 0;
    uint32_t bits = 0;
    const bool major = road.highway == HighwayClass::Motorway || road.highway == HighwayClass::Trunk ||
                       road.highway == HighwayClass::Primary;
    if (!road.oneway && road.lanes >= 2) {
        bits |= kMarkCentreLine;
        if (road.overtaking && !major) bits |= kMarkCentreDashed;
        if (american) bits |= kMarkCentreYellow;
    }
    const int perDirection = road.oneway ? road.lanes : road.lanes / 2;
    if (perDirection >= 2 || (road.oneway && road.lanes >= 2)) bits |= kMarkLaneDividers;
    if (road.highway == HighwayClass::Motorway || road.highway == HighwayClass::Trunk) bits |= kMarkEdgeLines;
    return bits;
}

} // namespace urbis
