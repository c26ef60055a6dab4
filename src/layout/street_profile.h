// The cross-section of a generated street: class, lanes, carriageway and sidewalk widths, as the
// OSM import would read them from tags, so that the same street code draws both cities.
#pragma once

#include "model/city_model.h"

namespace urbis {

struct StreetProfile {
    HighwayClass highway = HighwayClass::Residential;
    int lanes = 2;
    bool oneway = false;
    float width = 6.0f;          ///< m, carriageway: lanes times the class's lane width
    float sidewalkWidth = 2.5f;  ///< m, on each side
    /// Distance in metres from the centerline to the far edge of a sidewalk.
    double halfCorridor() const { return 0.5 * width + sidewalkWidth; }
    /// A road with this cross-section and no centerline yet: sidewalks both sides, asphalt, lanes
    /// split evenly between the directions (all forward when one-way), no overtaking on primaries.
    Road road() const;
};

/// The profile of a street of `highway` class with `lanes` lanes: lane and sidewalk widths by class
/// (primary 3.5 m and 4 m, secondary 3.25 m and 3.5 m, tertiary 3.25 m and 3 m, residential 3 m and
/// 2.5 m), never narrower than one 3.5 m lane.
StreetProfile streetProfile(HighwayClass highway, int lanes, bool oneway = false);

} // namespace urbis
