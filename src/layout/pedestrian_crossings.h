// Pedestrian crossings of the generated city, on some approaches to its junctions.
#pragma once

#include "layout/river.h"
#include "model/city_model.h"

#include <cstdint>
#include <vector>

namespace urbis {

/// Places crossings on some approaches to the junctions of `roads` (points shared by two roads or
/// more), each at a vertex inserted into the approaching road just outside the junction: the
/// crossing road's half carriageway and sidewalk (measured along the approach, so longer where
/// the roads meet at a slant) plus 2 m. Zebras on residential and tertiary streets, marked
/// crossings on avenues, traffic signals where a primary meets a primary or an avenue. None
/// where the next junction leaves no room, nor near the river (its bridges). Which approaches get
/// one depends on the seed and the junction's position only, so a larger city keeps them.
std::vector<Crossing> placeCrossings(std::vector<Road>& roads, uint32_t seed, const River& river);

} // namespace urbis
