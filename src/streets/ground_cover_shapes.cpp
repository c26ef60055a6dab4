#include "streets/ground_cover_shapes.h"

#include "model/geos_polygon.h"

#include <geos_c.h>

#include <algorithm>
#include <cmath>

namespace urbis {

namespace {

/// Anything with less area is no area (m^2): a sliver GEOS leaves behind when it makes a ring valid.
constexpr double kMinShapeArea = 1e-6;

bool usable(const Ring& ring) {
    if (ring.size() < 3) return false;
    for (const Vec2d p : ring)
        if (!(std::fabs(p.x) <= CoverShapes::kMaxCoordinate && std::fabs(p.y) <= CoverShapes::kMaxCoordinate)) return false;
    return true;
}

/// The polygonal parts of `g` (taken over) as one geometry: `g` itself when it is a polygon or a
/// multipolygon, else the union of the polygons in the collection (GEOSMakeValid_r may add the lines
/// that a collapsed ring leaves). Null when it holds no area.
GEOSGeometry* polygonalOnly(GEOSContextHandle_t ctx, GEOSGeometry* g) {
    if (!g) return nullptr;
    const int type = GEOSGeomTypeId_r(ctx, g);
    if (type == GEOS_GEOMETRYCOLLECTION) {
        std::vector<GEOSGeometry*> polygons;
        for (int i = 0, n = GEOSGetNumGeometries_r(ctx, g); i < n; ++i) {
            const GEOSGeometry* part = GEOSGetGeometryN_r(ctx, g, i);
            const int partType = GEOSGeomTypeId_r(ctx, part);
            if (partType == GEOS_POLYGON || partType == GEOS_MULTIPOLYGON) polygons.push_back(GEOSGeom_clone_r(ctx, part));
        }
        GEOSGeom_destroy_r(ctx, g);
        GEOSGeometry* collection =
            GEOSGeom_createCollection_r(ctx, GEOS_GEOMETRYCOLLECTION, polygons.data(), unsigned(polygons.size()));
        g = collection ? GEOSUnaryUnion_r(ctx, collection) : nullptr;
        if (collection) GEOSGeom_destroy_r(ctx, collection);
        if (!g) return nullptr;
    } else if (type != GEOS_POLYGON && type != GEOS_MULTIPOLYGON) {
        GEOSGeom_destroy_r(ctx, g);
        return nullptr;
    }
    double area = 0;
    if (GEOSArea_r(ctx, g, &area) != 1 || !(area >= kMinShapeArea)) {
        GEOSGeom_destroy_r(ctx, g);
        return nullptr;
    }
    return g;
}

PlaneBox boxOf(GEOSContextHandle_t ctx, const GEOSGeometry* g) {
    PlaneBox b;
    GEOSGeom_getXMin_r(ctx, g, &b[0].x);
    GEOSGeom_getYMin_r(ctx, g, &b[0].y);
    GEOSGeom_getXMax_r(ctx, g, &b[1].x);
    GEOSGeom_getYMax_r(ctx, g, &b[1].y);
    return b;
}

/// Appends GEOS's constrained Delaunay triangles of polygonal `g`; false on failure.
bool appendTriangles(GEOSContextHandle_t ctx, const GEOSGeometry* g, std::vector<PlaneTriangle>& out) {
    GEOSGeometry* all = GEOSConstrainedDelaunayTriangulation_r(ctx, g);
    if (!all) return false;
    bool ok = true;
    for (int i = 0, n = GEOSGetNumGeometries_r(ctx, all); i < n && ok; ++i) {
        const GEOSGeometry* ring = GEOSGetExteriorRing_r(ctx, GEOSGetGeometryN_r(ctx, all, i));
        const GEOSCoordSequence* sequence = ring ? GEOSGeom_getCoordSeq_r(ctx, ring) : nullptr;
        ok = sequence != nullptr;
        PlaneTriangle t;
        for (unsigned k = 0; k < 3 && ok; ++k) GEOSCoordSeq_getXY_r(ctx, sequence, k, &t[k].x, &t[k].y);
        if (ok) out.push_back(t);
    }
    GEOSGeom_destroy_r(ctx, all);
    return ok;
}

/// Pieces of at most this many points are triangulated whole. GEOS's triangulation clips ears in
/// time that grows faster than the square of the points (a 20,000-point ring took 1.3 s, 40,000 took
/// 19 s); in pieces of 512 a coastline's 40,000 take a fraction of that.
constexpr int kMaxPiecePoints = 128;
/// Halvings at most: a cluster of points tighter than the box / 2^24 is triangulated as it is.
constexpr int kMaxSplitDepth = 24;

/// The part of polygonal `g` in `box`, null when it has no area: GEOS's rectangle clipping (linear in
/// the points, where an overlay of a coastline's 40,000 took 0.2 s), or the overlay where the clipping
/// gave an invalid polygon, which it may.
GEOSGeometry* clipToBox(GEOSContextHandle_t ctx, const GEOSGeometry* g, const PlaneBox& box) {
    GEOSGeometry* piece = polygonalOnly(ctx, GEOSClipByRect_r(ctx, g, box[0].x, box[0].y, box[1].x, box[1].y));
    if (!piece || GEOSisValid_r(ctx, piece) == 1) return piece;
    GEOSGeom_destroy_r(ctx, piece);
    GEOSGeometry* rectangle = GEOSGeom_createRectangle_r(ctx, box[0].x, box[0].y, box[1].x, box[1].y);
    if (!rectangle) return nullptr;
    piece = polygonalOnly(ctx, GEOSIntersection_r(ctx, g, rectangle));
    GEOSGeom_destroy_r(ctx, rectangle);
    return piece;
}

/// Triangulates polygonal `g`, cut in two across the longer side of its box until each piece has at
/// most kMaxPiecePoints. The cuts add points only where the lines cross the rings, so the triangles
/// stay about one per point; false on failure.
bool triangulateInPieces(GEOSContextHandle_t ctx, const GEOSGeometry* g, int depth, std::vector<PlaneTriangle>& out) {
    if (GEOSGetNumCoordinates_r(ctx, g) <= kMaxPiecePoints || depth >= kMaxSplitDepth) return appendTriangles(ctx, g, out);
    const PlaneBox b = boxOf(ctx, g);
    PlaneBox low = b, high = b;
    if (b[1].x - b[0].x >= b[1].y - b[0].y) low[1].x = high[0].x = 0.5 * (b[0].x + b[1].x);
    else low[1].y = high[0].y = 0.5 * (b[0].y + b[1].y);
    for (const PlaneBox& cut : {low, high}) {
        GEOSGeometry* piece = clipToBox(ctx, g, cut);
        if (!piece) continue;   // nothing with area on this side
        const bool ok = triangulateInPieces(ctx, piece, depth + 1, out);
        GEOSGeom_destroy_r(ctx, piece);
        if (!ok) return false;
    }
    return true;
}

/// Triangulates the part of polygonal `g` in `box`, halving the box across its longer side while it
/// is wider than `cell` and comes within `band` of `boundary` (prepared); false on failure.
bool triangulateNear(GEOSContextHandle_t ctx, const GEOSGeometry* g, const GEOSPreparedGeometry* boundary,
                     const PlaneBox& box, double cell, double band, std::vector<PlaneTriangle>& out) {
    GEOSGeometry* rectangle = GEOSGeom_createRectangle_r(ctx, box[0].x, box[0].y, box[1].x, box[1].y);
    double distance = 0;
    const bool near = rectangle && GEOSPreparedDistance_r(ctx, boundary, rectangle, &distance) == 1 && distance < band;
    if (rectangle) GEOSGeom_destroy_r(ctx, rectangle);
    const double wide = std::max(box[1].x - box[0].x, box[1].y - box[0].y);
    double area = 0;
    if (wide <= cell && GEOSGetNumCoordinates_r(ctx, g) == 5 && GEOSArea_r(ctx, g, &area) == 1 &&
        area == (box[1].x - box[0].x) * (box[1].y - box[0].y)) {
        // The whole cell is in the shape: its two triangles, without a triangulation's cost.
        out.push_back({box[0], Vec2d{box[1].x, box[0].y}, box[1]});
        out.push_back({box[0], box[1], Vec2d{box[0].x, box[1].y}});
        return true;
    }
    if (!near || wide <= cell) return triangulateInPieces(ctx, g, 0, out);
    PlaneBox low = box, high = box;
    if (box[1].x - box[0].x >= box[1].y - box[0].y) low[1].x = high[0].x = 0.5 * (box[0].x + box[1].x);
    else low[1].y = high[0].y = 0.5 * (box[0].y + box[1].y);
    for (const PlaneBox& cut : {low, high}) {
        GEOSGeometry* piece = clipToBox(ctx, g, cut);
        if (!piece) continue;
        const bool ok = triangulateNear(ctx, piece, boundary, cut, cell, band, out);
        GEOSGeom_destroy_r(ctx, piece);
        if (!ok) return false;
    }
    return true;
}

} // namespace

bool boxesOverlap(const PlaneBox& a, const PlaneBox& b) {
    return a[0].x < b[1].x && b[0].x < a[1].x && a[0].y < b[1].y && b[0].y < a[1].y;
}

CoverShapes::CoverShapes() : handle_(GEOS_init_r()) {}

CoverShapes::~CoverShapes() {
    for (Shape& s : shapes_) GEOSGeom_destroy_r(handle_, s.geometry);
    GEOS_finish_r(handle_);
}

CoverShapes::Added CoverShapes::add(const Polygon& polygon) {
    const GEOSContextHandle_t ctx = handle_;
    if (!usable(polygon.outer)) return Added::Degenerate;
    GEOSGeometry* shell = geosRing(ctx, polygon.outer);
    if (!shell) return Added::Degenerate;
    std::vector<GEOSGeometry*> holes;
    for (const Ring& hole : polygon.holes) {
        GEOSGeometry* ring = usable(hole) ? geosRing(ctx, hole) : nullptr;
        if (ring) holes.push_back(ring);
        else ++holesSkipped;
    }
    GEOSGeometry* g = GEOSGeom_createPolygon_r(ctx, shell, holes.data(), unsigned(holes.size()));
    if (g && GEOSisValid_r(ctx, g) != 1) {
        GEOSGeometry* valid = GEOSMakeValid_r(ctx, g);
        GEOSGeom_destroy_r(ctx, g);
        g = valid;
    }
    g = polygonalOnly(ctx, g);
    if (!g) return Added::Degenerate;
    shapes_.push_back({g, boxOf(ctx, g)});
    return Added::Shape;
}

double CoverShapes::area(size_t shape) const {
    double a = 0;
    GEOSArea_r(handle_, shapes_[shape].geometry, &a);
    return a;
}

bool CoverShapes::overlap(size_t a, size_t b) const {
    if (!boxesOverlap(shapes_[a].box, shapes_[b].box)) return false;
    return GEOSRelatePattern_r(handle_, shapes_[a].geometry, shapes_[b].geometry, "T********") == 1;
}

bool CoverShapes::subtract(size_t shape, size_t cut) {
    const GEOSContextHandle_t ctx = handle_;
    Shape& s = shapes_[shape];
    GEOSGeometry* rest = polygonalOnly(ctx, GEOSDifference_r(ctx, s.geometry, shapes_[cut].geometry));
    if (!rest) return false;
    GEOSGeom_destroy_r(ctx, s.geometry);
    s = {rest, boxOf(ctx, rest)};
    return true;
}

std::vector<PlaneTriangle> CoverShapes::triangles(size_t shape) const {
    std::vector<PlaneTriangle> out;
    if (!triangulateInPieces(handle_, shapes_[shape].geometry, 0, out)) out.clear();
    return out;
}

std::vector<PlaneTriangle> CoverShapes::trianglesNearBoundary(size_t shape, double cell, double band) const {
    const GEOSContextHandle_t ctx = handle_;
    std::vector<PlaneTriangle> out;
    GEOSGeometry* boundary = GEOSBoundary_r(ctx, shapes_[shape].geometry);
    const GEOSPreparedGeometry* prepared = boundary ? GEOSPrepare_r(ctx, boundary) : nullptr;
    if (!prepared || !triangulateNear(ctx, shapes_[shape].geometry, prepared, shapes_[shape].box, cell, band, out))
        out.clear();
    if (prepared) GEOSPreparedGeom_destroy_r(ctx, prepared);
    if (boundary) GEOSGeom_destroy_r(ctx, boundary);
    return out;
}

std::vector<double> CoverShapes::distancesToBoundary(size_t shape, const std::vector<Vec2d>& points) const {
    const GEOSContextHandle_t ctx = handle_;
    std::vector<double> out(points.size(), 0.0);
    GEOSGeometry* boundary = GEOSBoundary_r(ctx, shapes_[shape].geometry);
    const GEOSPreparedGeometry* prepared = boundary ? GEOSPrepare_r(ctx, boundary) : nullptr;
    for (size_t i = 0; prepared && i < points.size(); ++i) {
        GEOSGeometry* point = GEOSGeom_createPointFromXY_r(ctx, points[i].x, points[i].y);
        if (point) GEOSPreparedDistance_r(ctx, prepared, point, &out[i]);
        if (point) GEOSGeom_destroy_r(ctx, point);
    }
    if (prepared) GEOSPreparedGeom_destroy_r(ctx, prepared);
    if (boundary) GEOSGeom_destroy_r(ctx, boundary);
    return out;
}

} // namespace urbis
