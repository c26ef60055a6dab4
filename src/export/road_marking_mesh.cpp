#include "export/road_marking_mesh.h"

#include "geometry/road_markings.h"
#include "scene/surface_part.h"

#include <algorithm>
#include <cmath>

namespace urbis {

namespace {

/// A point of a road triangle in its segment's coordinates (along, across) with its height.
struct RoadPoint {
    float along, across, y;
};

/// A painted rectangle of a segment: [along0, along1] x [across0, across1].
struct PaintRect {
    float along0, along1, across0, across1;
};

/// Keeps the part of `polygon` where `coordinate` (0: along, 1: across) times `sign` is at most
/// `limit` times `sign` (Sutherland-Hodgman against one line); y is linear along each edge.
std::vector<RoadPoint> clipTo(const std::vector<RoadPoint>& polygon, int coordinate, float limit, float sign) {
    const auto value = [&](const RoadPoint& p) { return sign * ((coordinate == 0 ? p.along : p.across) - limit); };
    std::vector<RoadPoint> out;
    for (size_t i = 0; i < polygon.size(); ++i) {
        const RoadPoint& a = polygon[i];
        const RoadPoint& b = polygon[(i + 1) % polygon.size()];
        const float va = value(a), vb = value(b);
        if (va <= 0.0f) out.push_back(a);
        if ((va < 0.0f && vb > 0.0f) || (va > 0.0f && vb < 0.0f)) {
            const float t = va / (va - vb);
            out.push_back({a.along + (b.along - a.along) * t, a.across + (b.across - a.across) * t, a.y + (b.y - a.y) * t});
        }
    }
    return out;
}

/// The rectangles of paint of one band, its lines each cut into its dashes, clipped to the carriageway.
void bandRects(const RoadSegment& s, const MarkingBand& b, std::vector<PaintRect>& out) {
    for (int32_t k = b.first; k <= b.last; ++k) {
        const float centre = b.across + float(k) * b.pitch;
        const float across0 = std::max(centre - b.halfWidth, -s.halfWidth), across1 = std::min(centre + b.halfWidth, s.halfWidth);
        const float from = std::max(b.alongFrom, 0.0f), to = std::min(b.alongTo, s.length);
        if (!(across0 < across1) || !(from < to)) continue;
        if (!(b.dashPeriod > 0.0f)) {
            out.push_back({from, to, across0, across1});
            continue;
        }
        for (float n = std::floor((b.roadDistance + from) / b.dashPeriod); b.dashStart(n) < to; n += 1.0f) {
            const float a0 = std::max(b.dashStart(n), from), a1 = std::min(b.dashStart(n) + b.dashLength, to);
            if (a0 < a1) out.push_back({a0, a1, across0, across1});
        }
    }
}

/// Smallest area (m^2) of a piece of paint kept: slivers where a rectangle grazes a triangle go.
constexpr float kMinPieceArea = 1e-6f;

/// The part of rectangle `r` of segment `s` over road triangle `tri`, lifted kMarkingLift and facing
/// up, as a fan of triangles.
void layOnTriangle(const RoadSegment& s, const PaintRect& r, const Triangle& tri, TriangleInfo info, TriangleMesh& out) {
    std::vector<RoadPoint> piece;
    for (const Vec3f& p : {tri.p0, tri.p1, tri.p2}) {
        const Vec2f road = roadCoordinates(s, p.x, p.z);
        piece.push_back({road.x, road.y, p.y});
    }
    piece = clipTo(clipTo(piece, 0, r.along0, -1.0f), 0, r.along1, 1.0f);
    piece = clipTo(clipTo(piece, 1, r.across0, -1.0f), 1, r.across1, 1.0f);
    // Back to world (x, z): the left of direction (dx, dz) is (dz, -dx) (roadCoordinates).
    const auto world = [&](const RoadPoint& p) {
        return Vec3f{s.start.x + p.along * s.direction.x + p.across * s.direction.y, p.y + kMarkingLift,
                     s.start.y + p.along * s.direction.y - p.across * s.direction.x};
    };
    for (size_t v = 1; v + 1 < piece.size(); ++v) {
        Triangle fan{world(piece[0]), world(piece[v]), world(piece[v + 1])};
        const Vec3f n = cross(fan.p1 - fan.p0, fan.p2 - fan.p0);
        if (!(std::fabs(n.y) > 2.0f * kMinPieceArea)) continue;
        if (n.y < 0.0f) std::swap(fan.p1, fan.p2);   // counter-clockwise from above: glTF's front face up
        out.add(fan, info);
    }
}

} // namespace

TriangleMesh roadMarkingMesh(const std::vector<RoadSegment>& segments, const TriangleMesh& mesh) {
    std::vector<std::vector<size_t>> trianglesOf(segments.size());
    for (size_t k = 0; k < mesh.size(); ++k)
        if (mesh.info[k].part == uint32_t(SurfacePart::Road) && mesh.info[k].object < segments.size())
            trianglesOf[mesh.info[k].object].push_back(k);

    TriangleMesh out;
    std::vector<PaintRect> rects;
    for (size_t i = 0; i < segments.size(); ++i) {
        const RoadSegment& s = segments[i];
        if (s.markings == 0) continue;
        forEachMarkingBand(s, [&](const MarkingBand& b) {
            rects.clear();
            bandRects(s, b, rects);
            const TriangleInfo info{s.paint + uint32_t(b.paint) - 1, s.object, uint32_t(SurfacePart::Road)};
            for (const PaintRect& r : rects)
                for (size_t t : trianglesOf[i]) layOnTriangle(s, r, mesh.triangles[t], info, out);
            return false;
        });
    }
    return out;
}

} // namespace urbis
