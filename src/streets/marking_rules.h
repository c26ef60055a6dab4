// Which lines a road carries, from its class, lanes and tags (host): the part of RoadSegment::markings
// that does not depend on junctions and crossings (streets' network adds stop lines and zebras).
#pragma once

#include "model/city_model.h"

#include <cstdint>

namespace urbis {

/// RoadMarking bits of `road`. None where `lane_markings=no`, on classes below residential (service
/// roads, living streets, pedestrian streets, paths, tracks) or on a surface paint does not take
/// (unpaved, sett, cobblestones, wood, metal). Else: a centre line on a two-way road of two lanes or
/// more and at least kCentreLineMinWidth wide, dashed unless `overtaking=no`, the road is a motorway or
/// a trunk, or it has two lanes or more each way; dashed dividers between the lanes of one direction;
/// edge lines on motorways and trunks. With `american` (the MUTCD's layout) the centre line is yellow
/// and kMarkAmerican is set.
uint32_t markingBits(const Road& road, bool american);

/// Whether a surface is paved (markings can be painted on it).
bool isPaved(RoadSurface surface);

/// m: narrower two-way roads get no centre line (Germany's RMS: 5.50 m; the MUTCD: 16-18 ft).
inline constexpr float kCentreLineMinWidth = 5.5f;

} // namespace urbis
