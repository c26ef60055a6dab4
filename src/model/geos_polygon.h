// Polygon validity, clipping and overlap through GEOS (thread-safe C API, one context per user), and the
// one conversion of a ring into GEOS that the importer and the ground cover share.
#pragma once

#include "model/city_model.h"

#include <vector>

struct GEOSContextHandle_HS; // geos_c.h's context type, kept out of this header
struct GEOSGeom_t;           // geos_c.h's geometry type

namespace urbis {

/// A closed GEOS linear ring of `ring` (local metres; the closing point, which a Ring leaves implicit,
/// repeated), owned by the caller; null where GEOS refuses the points. The one conversion into GEOS
/// for the importer's polygons and the ground cover's.
GEOSGeom_t* geosRing(GEOSContextHandle_HS* ctx, const Ring& ring);

/// What `GeosContext::makeValid` found.
enum class Validity { Valid, Repaired, Invalid };

/// Owns a GEOS context handle; not copyable.
class GeosContext {
public:
    GeosContext();
    ~GeosContext();
    GeosContext(const GeosContext&) = delete;
    GeosContext& operator=(const GeosContext&) = delete;

    /// Checks a polygon (local metres) with GEOSisValid_r. An invalid one (self-intersecting
    /// ring, crossing holes, ...) is replaced by the largest polygon GEOSMakeValid_r makes of
    /// it, oriented and without closing points (Repaired), or left as is when it makes none
    /// (Invalid).
    Validity makeValid(Polygon& polygon) const;

    /// The polygons of the part of a valid `polygon` inside the rectangle [min, max] (local
    /// metres), GEOSClipByRect_r: none when it lies outside, several when the border cuts it
    /// apart; oriented, without closing points.
    std::vector<Polygon> clipToRectangle(const Polygon& polygon, Vec2d min, Vec2d max) const;

    /// The ribbon `halfWidth` metres to each side of `line` (local metres, two or more points), flat
    /// at its ends, round at its bends (GEOSBufferWithStyle_r): one polygon, or several where the line
    /// crosses itself; oriented, without closing points.
    std::vector<Polygon> ribbonAround(const std::vector<Vec2d>& line, double halfWidth) const;

    /// Area in m^2 common to two valid polygons.
    double overlapArea(const Polygon& a, const Polygon& b) const;

private:
    GEOSContextHandle_HS* handle_;
};

} // namespace urbis
