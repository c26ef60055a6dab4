#include "citygen/building_mesher.h"

#include "citygen/footprint_cleaning.h"
#include "citygen/roof_mesher.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>

namespace urbis {

namespace {

struct GeometryDeleter {
    GEOSContextHandle_t geos;
    void operator()(GEOSGeometry* g) const { GEOSGeom_destroy_r(geos, g); }
};
using GeometryPtr = std::unique_ptr<GEOSGeometry, GeometryDeleter>;

/// A closed GEOS linear ring from a ring whose closing point is implicit; null on failure.
GEOSGeometry* makeLinearRing(GEOSContextHandle_t geos, const Ring& ring) {
    GEOSCoordSequence* seq = GEOSCoordSeq_create_r(geos, unsigned(ring.size() + 1), 2);
    if (!seq) return nullptr;
    for (size_t i = 0; i <= ring.size(); ++i) {
        const Vec2d& p = ring[i % ring.size()];
        GEOSCoordSeq_setXY_r(geos, seq, unsigned(i), p.x, p.y);
    }
    return GEOSGeom_createLinearRing_r(geos, seq);
}

GeometryPtr makePolygon(GEOSContextHandle_t geos, const Polygon& polygon) {
    GEOSGeometry* shell = makeLinearRing(geos, polygon.outer);
    if (!shell) return GeometryPtr(nullptr, {geos});
    std::vector<GEOSGeometry*> holes;
    for (const Ring& hole : polygon.holes)
        if (GEOSGeometry* h = makeLinearRing(geos, hole)) holes.push_back(h);
    return GeometryPtr(GEOSGeom_createPolygon_r(geos, shell, holes.data(), unsigned(holes.size())), {geos});
}

/// Triangles of a valid polygon in the city plane, from GEOS's constrained Delaunay triangulation.
bool triangulateFootprint(GEOSContextHandle_t geos, const GEOSGeometry* polygon, std::vector<std::array<Vec2d, 3>>& out) {
    GeometryPtr triangles(GEOSConstrainedDelaunayTriangulation_r(geos, polygon), {geos});
    if (!triangles) return false;
    int count = GEOSGetNumGeometries_r(geos, triangles.get());
    for (int i = 0; i < count; ++i) {
        const GEOSGeometry* ring = GEOSGetExteriorRing_r(geos, GEOSGetGeometryN_r(geos, triangles.get(), i));
        const GEOSCoordSequence* seq = ring ? GEOSGeom_getCoordSeq_r(geos, ring) : nullptr;
        if (!seq) return false;
        std::array<Vec2d, 3> tri;
        for (unsigned k = 0; k < 3; ++k) GEOSCoordSeq_getXY_r(geos, seq, k, &tri[k].x, &tri[k].y);
        out.push_back(tri);
    }
    return count > 0;
}

/// Twice the signed area of a ring (positive when counter-clockwise).
double signedArea2(const Ring& ring) {
    double a = 0;
    for (size_t i = 0; i < ring.size(); ++i) {
        const Vec2d& p = ring[i];
        const Vec2d& q = ring[(i + 1) % ring.size()];
        a += p.x * q.y - q.x * p.y;
    }
    return a;
}

/// How far the building reaches behind the edge a -> b whose outside normal is `outward`: the
/// largest distance of an outer-ring point on the inner side.
float depthBehind(const Ring& outer, Vec2d a, Vec2d outward) {
    double depth = 0;
    for (const Vec2d& p : outer) depth = std::max(depth, -((p.x - a.x) * outward.x + (p.y - a.y) * outward.y));
    return float(depth);
}

/// The roof's parapet bands, found by their footprint edge.
class ParapetBands {
public:
    explicit ParapetBands(const RoofResult& roof) : bands_(roof.parapetBands) {
        std::sort(bands_.begin(), bands_.end(), [](const ParapetBand& x, const ParapetBand& y) { return before(x.p0, y.p0); });
    }
    /// The band over the edge a -> b, or null.
    const ParapetBand* find(Vec2d a, Vec2d b) const {
        auto it = std::lower_bound(bands_.begin(), bands_.end(), a, [](const ParapetBand& x, Vec2d p) { return before(x.p0, p); });
        for (; it != bands_.end() && it->p0.x == a.x && it->p0.y == a.y; ++it)
            if (it->p1.x == b.x && it->p1.y == b.y) return &*it;
        return nullptr;
    }

private:
    static bool before(Vec2d p, Vec2d q) { return p.x < q.x || (p.x == q.x && p.y < q.y); }
    std::vector<ParapetBand> bands_;
};

/// Gives `wall` (on the edge a -> b) the parapet over `band`: its inner face's ends along the edge.
void putParapetOnWall(const ParapetBand& band, const RoofResult& roof, Vec2d a, Vec2d b, WallRecord& wall) {
    const double dx = b.x - a.x, dy = b.y - a.y, len = std::sqrt(dx * dx + dy * dy);
    auto along = [&](Vec2d q) { return float(((q.x - a.x) * dx + (q.y - a.y) * dy) / len); };
    wall.parapetHeight = float(roof.parapetHeight);
    wall.parapetThickness = float(roof.parapetThickness);
    wall.parapetInner0 = along(band.q0);
    wall.parapetInner1 = along(band.q1);
}

/// One wall per ring edge: a procedural wall record where the edge is large enough for a facade
/// (and `facade` is given), else a plain quad of two triangles. The edge's parapet band goes on its
/// wall record where there is one and parapets are procedural, else it is meshed.
void addWalls(const Ring& ring, bool isHole, const Ring& outer, double bottom, const RoofResult& roof,
              const ParapetBands& bands, const RoofSink& roofSink, TriangleInfo info, const WallContext* facade,
              uint32_t& wallIndex, TriangleMesh& mesh, std::vector<WallRecord>& walls, BuildingTriangleCounts& counts) {
    const double top = roof.wallTop;
    const double area = signedArea2(ring);
    const bool outsideRight = isHole ? area < 0.0 : area > 0.0;
    auto meshBand = [&](const ParapetBand* band) {
        if (!band) return;
        RoofSink sink = roofSink;
        meshParapetBand(*band, roof.parapetHeight, sink);
        counts.walls += sink.wallTriangles;
    };
    for (size_t i = 0; i < ring.size(); ++i) {
        Vec2d a = ring[i], b = ring[(i + 1) % ring.size()];
        const uint32_t index = wallIndex++;
        const ParapetBand* band = bands.find(a, b);
        if (facade) {
            const double dx = b.x - a.x, dy = b.y - a.y, len = std::sqrt(dx * dx + dy * dy);
            const double side = outsideRight ? 1.0 : -1.0;
            const Vec2d outward{len > 0 ? side * dy / len : 0.0, len > 0 ? -side * dx / len : 0.0};
            WallRecord wall;
            if (layoutWall(*facade, a, b, outsideRight, float(bottom), float(top), depthBehind(outer, a, outward),
                           float(roof.parapetHeight), index, wall)) {
                if (band && facade->proceduralParapets) putParapetOnWall(*band, roof, a, b, wall);
                else meshBand(band);
                walls.push_back(wall);
                ++counts.wallRecords;
                continue;
            }
        }
        Vec3f a0 = worldFromCity(a, bottom), b0 = worldFromCity(b, bottom);
        Vec3f a1 = worldFromCity(a, top), b1 = worldFromCity(b, top);
        mesh.add({a0, b0, b1}, info);
        mesh.add({a0, b1, a1}, info);
        counts.walls += 2;
        ++counts.plainWalls;
        meshBand(band);
    }
}

} // namespace

const char* meshBuilding(GEOSContextHandle_t geos, const Building& original, TriangleInfo wallInfo, TriangleInfo roofInfo,
                         const WallContext* facade, TriangleMesh& mesh, std::vector<WallRecord>& walls,
                         BuildingTriangleCounts& counts) {
    std::optional<CleanedFootprint> cleaned = cleanFootprint(original.footprint);
    if (!cleaned) return "degenerate_footprint";
    Building building = original;
    building.footprint = std::move(cleaned->polygon);
    const GeometryPtr polygon = makePolygon(geos, building.footprint);
    if (!polygon || GEOSisValid_r(geos, polygon.get()) != 1) return "invalid_footprint";
    std::vector<std::array<Vec2d, 3>> footprint;
    if (!triangulateFootprint(geos, polygon.get(), footprint)) return "triangulation_failed";
    counts.holesDropped += cleaned->holesDropped;
    const RoofResult roof = meshRoof(building, footprint, roofInfo, wallInfo, mesh);
    counts.roofs += roof.roofTriangles;
    counts.walls += roof.wallTriangles;
    for (const char* reason : roof.fallbacks) ++counts.roofFallbacks[reason];
    const double bottom = building.minHeight;
    if (bottom > 0.0) {
        for (const auto& t : footprint)
            mesh.add({worldFromCity(t[0], bottom), worldFromCity(t[1], bottom), worldFromCity(t[2], bottom)}, wallInfo);
        counts.walls += footprint.size();
    }
    const Ring& outer = building.footprint.outer;
    const ParapetBands bands(roof);
    const RoofSink roofSink{mesh, roofInfo, wallInfo, roof.wallTop};
    uint32_t wallIndex = 0;
    addWalls(outer, false, outer, bottom, roof, bands, roofSink, wallInfo, facade, wallIndex, mesh, walls, counts);
    for (const Ring& hole : building.footprint.holes)
        addWalls(hole, true, outer, bottom, roof, bands, roofSink, wallInfo, facade, wallIndex, mesh, walls, counts);
    return nullptr;
}

} // namespace urbis
