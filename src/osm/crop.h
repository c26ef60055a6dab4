// The crop box in degrees and clipping of polylines to it.
#pragma once

#include "osm/geo_projection.h"

#include <vector>

namespace urbis {

/// An axis-aligned box in degrees (WGS84).
struct GeoBox {
    double minLon = 0, minLat = 0, maxLon = 0, maxLat = 0;
    /// Whether the box has positive width and height.
    bool valid() const { return minLon < maxLon && minLat < maxLat; }
    /// Whether a position lies inside the box or on its border.
    bool contains(LonLat p) const {
        return p.lon >= minLon && p.lon <= maxLon && p.lat >= minLat && p.lat <= maxLat;
    }
    /// The centre in degrees.
    LonLat centre() const { return {0.5 * (minLon + maxLon), 0.5 * (minLat + maxLat)}; }
};

/// The pieces of a polyline inside the box, each segment clipped at the border
/// (Liang-Barsky, in degrees). A line that leaves and re-enters gives several pieces.
std::vector<std::vector<LonLat>> clipPolyline(const std::vector<LonLat>& line, const GeoBox& box);

} // namespace urbis
