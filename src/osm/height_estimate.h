// Heights of the buildings that carry no height or levels tag, estimated once the whole city
// is read and projected (neighbours and region are known only then).
#pragma once

#include "model/city_model.h"
#include "osm/import_options.h"

namespace urbis {

/// Radius in metres within which tagged buildings count as neighbours, and how many of the
/// building's type must stand there for their median to be used.
inline constexpr double kHeightNeighbourRadius = 150.0;
inline constexpr size_t kMinHeightNeighbours = 3;

/// Gives every building whose height is not tagged (!isTagged(heightSource)) a height above
/// its base, the first that applies of:
/// - options.untaggedHeightRange: uniform in it, seeded by (options.seed, osmId) (Range);
/// - the median height above base of the tagged buildings of the same type whose centroids lie
///   within kHeightNeighbourRadius of its centroid, if at least kMinHeightNeighbours, else
///   within twice that radius (NearbyMedian);
/// - typicalHeight(type, regionOf(city origin)), varied uniformly within the span by
///   (options.seed, osmId) (TypeTable).
/// A tagged roof keeps at least one storey (options.metresPerLevel) under it. Only tagged
/// buildings are neighbours, so the result depends on neither order nor threads.
void estimateHeights(CityModel& city, const ImportOptions& options);

} // namespace urbis
