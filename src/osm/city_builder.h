// From RawFeatures (degrees) to a CityModel (local metres): project, crop, clean, validate.
#pragma once

#include "model/city_model.h"
#include "osm/crop.h"
#include "osm/raw_features.h"

namespace urbis {

/// Builds the CityModel of `raw` cropped to `box`, on the tangent plane at the box's
/// centre. A building or area polygon is kept when it has 3+ distinct points, it is valid (or
/// GEOS repairs it: "made_valid" in CityModel::repaired), it covers 1 m^2 and, for buildings
/// and parts, its centroid lies in the box and it is not underground
/// (RawBuilding::underground: "underground"); an area is clipped to the box instead (each
/// piece of 1 m^2 or more kept; none: "area_outside_bbox"). Roads and railways are clipped to
/// the box; lamps, trees and crossings must lie in it (a crossing is projected as the road
/// vertex at the same node is, so the two are equal bit for bit). Rings come out without duplicate or closing points, outer
/// counter-clockwise, holes clockwise. Everything dropped is recorded with its id in
/// CityModel::dropped (see dropKey), the repairs and tag problems of kept objects in
/// CityModel::repaired; building:parts then replace their outlines (an underground part is
/// dropped first and replaces nothing). `source` and the boxes are left empty.
CityModel buildCityModel(RawFeatures&& raw, const GeoBox& box);

} // namespace urbis
