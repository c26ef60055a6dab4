// Which lines a road carries, from its class, lanes and tags (host): the part of RoadSegment::markings
// that does not depend on junctions and crossings (streets' network adds stop lines and zebras).
#pragma once

#include "model/city_model.h"

#include <cstdint>

namespace urbis {

/// RoadMarking bits of `road`: none where `lane_markings=no`, on service roads, living streets,
/// pedestrian streets, paths and tracks, or on an unpaved surface; else a centre line on a two-way
/// road of two lanes or more (dashed where overtaking is allowed and the class is below primary, yellow
/// with `american`), dashed dividers between lanes of one direction, and edge lines on motorways and
/// trunk roads.
uint32_t markingBits(const Road& road, bool american);

/// Whether a surface is paved (markings can be painted on it).
bool isPaved(RoadSurface surface);

} // namespace urbis
