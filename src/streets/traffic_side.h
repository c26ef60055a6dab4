// Which side of the road traffic keeps, by place (host): it mirrors the lanes and the stop lines.
#pragma once

#include "model/city_model.h"

#include <cstdint>

namespace urbis {

enum class TrafficSide : uint8_t { Right, Left };

/// The side traffic keeps at a place (degrees, WGS84): Left inside one of a table of boxes drawn round
/// the left-hand-traffic countries that urban extracts come from (Great Britain and Ireland, Malta,
/// Cyprus, Japan, Hong Kong and Macau, India, Nepal, Bangladesh and Sri Lanka, Pakistan's east,
/// Thailand's south, Malaysia, Singapore, Indonesia, Papua New Guinea, Australia, New Zealand,
/// southern and East Africa, Jamaica); Right elsewhere. The boxes follow borders only roughly (a
/// few kilometres off along land borders): the scene key `geometry.traffic` overrides them.
TrafficSide trafficSideAt(double latitude, double longitude);

/// The side for a city placed at `origin`: trafficSideAt its point, Right for a city placed nowhere
/// (the generated city).
TrafficSide trafficSideOf(const GeoOrigin& origin);

} // namespace urbis
