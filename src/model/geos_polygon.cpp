#include "model/geos_polygon.h"

#include "model/polygon_ops.h"

#include <geos_c.h>

#include <memory>
#include <vector>

namespace urbis {

namespace {

using Handle = GEOSContextHandle_t;

struct GeometryDeleter {
    Handle ctx;
    void operator()(GEOSGeometry* g) const { GEOSGeom_destroy_r(ctx, g); }
};
using GeometryPtr = std::unique_ptr<GEOSGeometry, GeometryDeleter>;

GeometryPtr toGeos(Handle ctx, const Polygon& polygon) {
    GEOSGeometry* shell = geosRing(ctx, polygon.outer);
    std::vector<GEOSGeometry*> holes;
    for (const Ring& hole : polygon.holes) holes.push_back(geosRing(ctx, hole));
    return GeometryPtr(GEOSGeom_createPolygon_r(ctx, shell, holes.data(), unsigned(holes.size())),
                       GeometryDeleter{ctx});
}

Ring fromGeosRing(Handle ctx, const GEOSGeometry* ring) {
    const GEOSCoordSequence* seq = GEOSGeom_getCoordSeq_r(ctx, ring);
    unsigned n = 0;
    GEOSCoordSeq_getSize_r(ctx, seq, &n);
    Ring out(n);
    for (unsigned i = 0; i < n; ++i) GEOSCoordSeq_getXY_r(ctx, seq, i, &out[i].x, &out[i].y);
    removeDuplicatePoints(out);
    return out;
}

Polygon fromGeos(Handle ctx, const GEOSGeometry* polygon) {
    Polygon out;
    out.outer = fromGeosRing(ctx, GEOSGetExteriorRing_r(ctx, polygon));
    for (int i = 0, n = GEOSGetNumInteriorRings_r(ctx, polygon); i < n; ++i)
        out.holes.push_back(fromGeosRing(ctx, GEOSGetInteriorRingN_r(ctx, polygon, i)));
    orient(out);
    return out;
}

/// The polygons of `geometry` (a polygon or a collection), oriented, without closing points; none empty.
std::vector<Polygon> polygonsOf(Handle ctx, const GEOSGeometry* geometry) {
    std::vector<Polygon> parts;
    if (!geometry) return parts;
    for (int i = 0, n = GEOSGetNumGeometries_r(ctx, geometry); i < n; ++i) {
        const GEOSGeometry* part = GEOSGetGeometryN_r(ctx, geometry, i);
        if (GEOSGeomTypeId_r(ctx, part) != GEOS_POLYGON || GEOSisEmpty_r(ctx, part) == 1) continue;
        Polygon p = fromGeos(ctx, part);
        if (p.outer.size() >= 3) parts.push_back(std::move(p));
    }
    return parts;
}

} // namespace

GEOSGeometry* geosRing(GEOSContextHandle_t ctx, const Ring& ring) {
    std::vector<double> xy;
    xy.reserve(2 * ring.size() + 2);
    for (const Vec2d p : ring) xy.insert(xy.end(), {p.x, p.y});
    xy.insert(xy.end(), {ring.front().x, ring.front().y});
    GEOSCoordSequence* sequence = GEOSCoordSeq_copyFromBuffer_r(ctx, xy.data(), ring.size() + 1, 0, 0);
    return sequence ? GEOSGeom_createLinearRing_r(ctx, sequence) : nullptr;
}

GeosContext::GeosContext() : handle_(GEOS_init_r()) {}

GeosContext::~GeosContext() { GEOS_finish_r(handle_); }

Validity GeosContext::makeValid(Polygon& polygon) const {
    const Handle ctx = handle_;
    const GeometryPtr geometry = toGeos(ctx, polygon);
    if (GEOSisValid_r(ctx, geometry.get()) == 1) return Validity::Valid;
    const GeometryPtr valid(GEOSMakeValid_r(ctx, geometry.get()), GeometryDeleter{ctx});
    if (!valid) return Validity::Invalid;
    const GEOSGeometry* largest = nullptr;
    double largestArea = 0;
    for (int i = 0, n = GEOSGetNumGeometries_r(ctx, valid.get()); i < n; ++i) {
        const GEOSGeometry* part = GEOSGetGeometryN_r(ctx, valid.get(), i);
        double a = 0;
        if (GEOSGeomTypeId_r(ctx, part) == GEOS_POLYGON && GEOSArea_r(ctx, part, &a) == 1 && a > largestArea) {
            largest = part;
            largestArea = a;
        }
    }
    if (!largest) return Validity::Invalid;
    polygon = fromGeos(ctx, largest);
    return Validity::Repaired;
}

std::vector<Polygon> GeosContext::clipToRectangle(const Polygon& polygon, Vec2d min, Vec2d max) const {
    const Handle ctx = handle_;
    const GeometryPtr geometry = toGeos(ctx, polygon);
    const GeometryPtr clipped(GEOSClipByRect_r(ctx, geometry.get(), min.x, min.y, max.x, max.y), GeometryDeleter{ctx});
    return polygonsOf(ctx, clipped.get());
}

std::vector<Polygon> GeosContext::ribbonAround(const std::vector<Vec2d>& line, double halfWidth) const {
    const Handle ctx = handle_;
    std::vector<Polygon> parts;
    if (line.size() < 2) return parts;
    std::vector<double> xy;
    for (const Vec2d p : line) xy.insert(xy.end(), {p.x, p.y});
    GEOSCoordSequence* sequence = GEOSCoordSeq_copyFromBuffer_r(ctx, xy.data(), unsigned(line.size()), 0, 0);
    if (!sequence) return parts;
    const GeometryPtr path(GEOSGeom_createLineString_r(ctx, sequence), GeometryDeleter{ctx});
    if (!path) return parts;
    const GeometryPtr ribbon(GEOSBufferWithStyle_r(ctx, path.get(), halfWidth, 4, GEOSBUF_CAP_FLAT, GEOSBUF_JOIN_ROUND, 5.0),
                             GeometryDeleter{ctx});
    return polygonsOf(ctx, ribbon.get());
}

double GeosContext::overlapArea(const Polygon& a, const Polygon& b) const {
    const Handle ctx = handle_;
    const GeometryPtr ga = toGeos(ctx, a), gb = toGeos(ctx, b);
    const GeometryPtr common(GEOSIntersection_r(ctx, ga.get(), gb.get()), GeometryDeleter{ctx});
    double result = 0;
    if (common) GEOSArea_r(ctx, common.get(), &result);
    return result;
}

} // namespace urbis
