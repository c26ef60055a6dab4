// How well untagged heights are estimated: tagged buildings are hidden and guessed back.
#pragma once

#include "model/city_model.h"
#include "osm/import_options.h"

#include <cstddef>

namespace urbis {

/// Absolute errors in metres of estimated heights against the hidden tagged ones.
struct HeightError {
    size_t hidden = 0;     ///< buildings whose height tags were hidden
    double median = 0;     ///< m, 0 when none was hidden
    double p90 = 0;        ///< m, 90th percentile
};

/// Hides the height and levels tags of a half of the tagged buildings of an imported `city`,
/// chosen by a hash of (options.seed, osm id), estimates them from the other half with
/// estimateHeights(options), and compares the estimated height above the base with the
/// tagged one. With options.untaggedHeightRange set this measures that seeded range instead.
HeightError evaluateHeightEstimate(const CityModel& city, const ImportOptions& options);

} // namespace urbis
