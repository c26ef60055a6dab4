// The OSM importer: an OpenStreetMap file in, a CityModel in local metres out.
#pragma once

#include "model/city_model.h"
#include "osm/import_options.h"

#include <nlohmann/json_fwd.hpp>

#include <string>

namespace urbis {

/// Reads an OSM file (.osm, .osm.pbf, .osm.bz2, .osm.gz; the format comes from the name)
/// with libosmium into a CityModel: buildings and building:parts (outer rings + holes;
/// a building outline that holds parts is replaced by them; underground ones dropped, see
/// isUnderground; untagged colours from the region's palette, see paintUntaggedBuildings),
/// roads, street lamps, trees, parks and water. Everything is projected to metres on the plane tangent to the WGS84
/// ellipsoid at the centre of the crop box (options.bbox, else the header box, else the
/// data extent) and cropped to that box. Buildings without height tags get estimated
/// heights (estimateHeights, osm/height_estimate.h). Objects that cannot be used are dropped and
/// recorded in CityModel::dropped by reason with their ids, objects kept after a fix in
/// CityModel::repaired; neither is fatal.
/// Throws InputError with one line "<path>: <problem>" for a missing, unreadable or
/// malformed file, bad options, or a box that holds no building.
CityModel importOsm(const std::string& path, const ImportOptions& options);

/// The JSON object `urbis inspect --json` prints for a city: counts (buildings, all
/// building records including parts; building_parts; roads; lamps; trees; parks; water),
/// dropped and repaired (reason -> count; with `ids` also dropped_ids and repaired_ids,
/// reason -> ["w123", "r456", "n789", ...]), extent_m {width, depth} of the model's geometry
/// in metres, bounds {kept, header, crop: {min_lon, min_lat, max_lon, max_lat} or null;
/// crop_source: "bbox", "header" or "data_extent"} in degrees, origin {lat, lon} in degrees,
/// source, and heights: buildings by HeightSource (from_height_tag, from_levels,
/// from_nearby_median, from_type_table, and from_range: the explicit seeded range of
/// ImportOptions::untaggedHeightRange). docs/cli.md lists the reasons.
nlohmann::json inspectJson(const CityModel& city, bool ids = false);

} // namespace urbis
