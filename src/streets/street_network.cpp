#include "streets/street_network.h"

#include "scene/road_segment.h"
#include "scene/surface_part.h"
#include "streets/junction_shapes.h"
#include "streets/marking_rules.h"
#include "streets/polyline.h"
#include "streets/road_fitting.h"
#include "streets/street_levels.h"
#include "streets/street_materials.h"
#include "streets/street_network_plane.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <unordered_set>

namespace urbis {

namespace {

/// Triangles thinner than this (m^2 in plan, or m^2 upright) are left out.
constexpr double kMinArea = 1e-8;
/// A trimmed centerline drops a vertex this close (m) to its new end.
constexpr double kMinSegment = 1e-4;

/// The material a road's surface is drawn in: paths' untagged surfaces by class.
StreetMaterial surfaceMaterial(const Road& road) {
    if (road.surface != RoadSurface::Unknown || !isPath(road.highway)) return materialOf(road.surface);
    switch (road.highway) {
    case HighwayClass::Cycleway: return StreetMaterial::Asphalt;
    case HighwayClass::Path: return StreetMaterial::Gravel;
    default: return StreetMaterial::PavingStones;
    }
}

/// A centerline cut to [from, to] m along it, with each point's elevation and distance along.
struct TrimmedLine {
    std::vector<Vec2d> points;
    std::vector<float> elevation;
    std::vector<double> distance;
};

TrimmedLine trimLine(const std::vector<Vec2d>& line, const std::vector<float>& elevation, double from, double to) {
    TrimmedLine out;
    const auto elevationAt = [&](size_t i) { return i < elevation.size() ? elevation[i] : 0.0f; };
    const auto add = [&](Vec2d p, float e, double s) {
        if (!out.points.empty() && s - out.distance.back() < kMinSegment) return;
        out.points.push_back(p);
        out.elevation.push_back(e);
        out.distance.push_back(s);
    };
    double s = 0;
    for (size_t i = 0; i + 1 < line.size(); ++i) {
        const double l = length(line[i + 1] - line[i]), s1 = s + l;
        const auto at = [&](double x) {
            const double f = l > 0 ? (x - s) / l : 0.0;
            return std::pair{f == 0 ? line[i] : line[i] + (line[i + 1] - line[i]) * f,
                             float(elevationAt(i) + (elevationAt(i + 1) - elevationAt(i)) * f)};
        };
        if (out.points.empty() && from <= s1) {
            const auto [p, e] = at(std::max(from, s));
            add(p, e, std::max(from, s));
        }
        if (!out.points.empty()) {
            if (to <= s1) {
                const auto [p, e] = at(to);
                if (to - out.distance.back() < kMinSegment && out.points.size() > 1) {
                    out.points.back() = p;   // the end replaces a vertex just before it
                    out.elevation.back() = e;
                    out.distance.back() = to;
                } else add(p, e, to);
                return out;
            }
            if (s1 - from > kMinSegment && to - s1 > kMinSegment) add(line[i + 1], elevationAt(i + 1), s1);
        }
        s = s1;
    }
    return out;
}

/// Ear clipping of a simple ring (either orientation; repeated points are dropped): triangles as
/// index triples into `ring`, counter-clockwise. A ring that folds on itself leaves its rest
/// untriangulated and counts it in `folded`.
std::vector<std::array<size_t, 3>> triangulateRing(const std::vector<Vec2d>& ring, uint64_t& folded) {
    std::vector<size_t> left;
    for (size_t i = 0; i < ring.size(); ++i)
        if (left.empty() || length(ring[i] - ring[left.back()]) > kMinSegment) left.push_back(i);
    while (left.size() > 1 && length(ring[left.front()] - ring[left.back()]) <= kMinSegment) left.pop_back();
    double area = 0;
    for (size_t i = 0; i < left.size(); ++i) area += cross(ring[left[i]], ring[left[(i + 1) % left.size()]]);
    if (area < 0) std::reverse(left.begin(), left.end());
    std::vector<std::array<size_t, 3>> out;
    const auto inTriangle = [&](Vec2d p, Vec2d a, Vec2d b, Vec2d c) {
        return cross(b - a, p - a) > 0 && cross(c - b, p - b) > 0 && cross(a - c, p - c) > 0;
    };
    while (left.size() > 3) {
        bool clipped = false;
        for (size_t k = 0; k < left.size() && !clipped; ++k) {
            const size_t ia = left[(k + left.size() - 1) % left.size()], ib = left[k], ic = left[(k + 1) % left.size()];
            const Vec2d a = ring[ia], b = ring[ib], c = ring[ic];
            if (!(cross(b - a, c - b) > kMinArea)) continue;
            bool empty = true;
            for (size_t m : left)
                if (m != ia && m != ib && m != ic && inTriangle(ring[m], a, b, c)) empty = false;
            if (!empty) continue;
            out.push_back({ia, ib, ic});
            left.erase(left.begin() + long(k));
            clipped = true;
        }
        if (!clipped) {
            ++folded;
            return out;
        }
    }
    if (left.size() == 3) out.push_back({left[0], left[1], left[2]});
    return out;
}

Vec3f world(Vec2d p, float height) { return {float(p.x), height, float(-p.y)}; }

class NetworkMesher {
public:
    NetworkMesher(const CityModel& city, const std::vector<Road>& roads, const std::vector<std::vector<float>>& elevations,
                  const StreetOptions& options, StreetMesh& out)
        : roads_(roads), elevations_(elevations), options_(options), out_(out),
          firstObject_(options.firstObject + out.objects) {
        for (const Crossing& c : city.crossings)
            if (c.kind == CrossingKind::Zebra || c.kind == CrossingKind::Marked) zebras_.insert(PointKey(c.position));
    }

    void run() {
        const StreetJunctions shapes = shapeJunctions(roads_, elevations_);
        for (uint32_t r = 0; r < roads_.size(); ++r) {
            if (shapes.consumed[r]) {
                ++out_.dropped[isPath(roads_[r].highway) ? "path_inside_carriageway" : "road_inside_junction"];
                continue;
            }
            meshRoad(r, shapes.starts[r], shapes.ends[r]);
        }
        for (const JunctionShape& j : shapes.junctions) meshJunction(j);
        for (const SidewalkCorner& c : shapes.corners) meshCorner(c);
        out_.counts["roads"] += roadsDrawn_;
        out_.counts["paths"] += pathsDrawn_;
        out_.counts["junctions"] += shapes.junctions.size();
        out_.counts["crossings"] += zebrasFound_.size();
        out_.objects += uint32_t(roads_.size());
        if (folded_ > 0) out_.dropped["junction_folded_ring"] += folded_;
        for (const auto& [kind, n] : trianglesOf_) out_.trianglesByKind[kind] += n;
    }

private:
    TriangleInfo info(StreetMaterial m, uint32_t object, SurfacePart part) const {
        TriangleInfo i;
        i.material = options_.firstMaterial + uint32_t(m);
        i.object = object;
        i.part = uint32_t(part);
        return i;
    }

    /// One triangle, counted under `kind`; thin ones are skipped.
    void triangle(Vec3f a, Vec3f b, Vec3f c, TriangleInfo i, const char* kind) {
        const Vec3f n = cross(b - a, c - a);
        if (!(dot(n, n) > kMinArea * kMinArea)) return;
        out_.mesh.add({a, b, c}, i);
        ++trianglesOf_[kind];
    }
    void quad(Vec3f a, Vec3f b, Vec3f c, Vec3f d, TriangleInfo i, const char* kind) {
        triangle(a, b, c, i, kind);
        triangle(a, c, d, i, kind);
    }
    /// Upright faces along a chain of plan points, from `bottom` to `top` above each point's elevation.
    void faces(const std::vector<Vec2d>& chain, const std::vector<float>& elevation, float bottom, float top,
               TriangleInfo i, const char* kind) {
        for (size_t k = 0; k + 1 < chain.size(); ++k) {
            // Down to the ground only where the street lies on it: under lifted parts the bridges'
            // structure stands (deck sides, embankment walls), in the same planes.
            if (bottom == 0.0f && (elevation[k] > 0.0f || elevation[k + 1] > 0.0f)) continue;
            quad(world(chain[k], elevation[k] + bottom), world(chain[k + 1], elevation[k + 1] + bottom),
                 world(chain[k + 1], elevation[k + 1] + top), world(chain[k], elevation[k] + top), i, kind);
        }
    }
    /// A flat strip between two chains of plan points at `height`, zipped along the shorter diagonals.
    void strip(const std::vector<Vec2d>& a, const std::vector<Vec2d>& b, float height, TriangleInfo i, const char* kind) {
        size_t p = 0, q = 0;
        while (p + 1 < a.size() || q + 1 < b.size()) {
            const bool advanceA = q + 1 == b.size() ||
                                  (p + 1 < a.size() && length(a[p + 1] - b[q]) < length(a[p] - b[q + 1]));
            if (advanceA) {
                triangle(world(a[p], height), world(b[q], height), world(a[p + 1], height), i, kind);
                ++p;
            } else {
                triangle(world(a[p], height), world(b[q], height), world(b[q + 1], height), i, kind);
                ++q;
            }
        }
    }

    void meshRoad(uint32_t r, const RoadEnd& start, const RoadEnd& end) {
        const Road& road = roads_[r];
        const bool path = isPath(road.highway);
        static const std::vector<float> kNone;
        const std::vector<float>& elevation = r < elevations_.size() ? elevations_[r] : kNone;
        const double total = polylineLength(road.centerline);
        const TrimmedLine line = trimLine(road.centerline, elevation, start.trim, total - end.trim);
        if (line.points.size() < 2) {
            ++out_.dropped["road_degenerate"];
            return;
        }
        const double half = road.width * 0.5;
        std::vector<Vec2d> left = offsetPolyline(line.points, half), right = offsetPolyline(line.points, -half);
        left.front() = start.left;
        right.front() = start.right;
        left.back() = end.left;
        right.back() = end.right;
        const uint32_t object = firstObject_ + r;
        const StreetMaterial material = surfaceMaterial(road);
        const char* kind = path ? "sidewalks" : "roads";
        const float level = path ? kPathLevel : kRoadLevel;
        (path ? pathsDrawn_ : roadsDrawn_) += 1;

        const uint32_t baseMarkings = path ? 0 : markingBits(road, options_.americanMarkings);
        const size_t last = line.points.size() - 2;
        for (size_t k = 0; k + 1 < line.points.size(); ++k) {
            const Vec2d a = line.points[k], b = line.points[k + 1];
            TriangleInfo i = info(material, object, path ? SurfacePart::Sidewalk : SurfacePart::Road);
            if (!path) {
                i.object = uint32_t(out_.roadSegments.size());
                out_.roadSegments.push_back(segment(road, object, a, b, line.distance[k], baseMarkings,
                                                    k == 0 && start.atJunction, k == last && end.atJunction));
            }
            const float ea = level + line.elevation[k], eb = level + line.elevation[k + 1];
            quad(world(right[k], ea), world(right[k + 1], eb), world(left[k + 1], eb), world(left[k], ea), i, kind);
        }
        // Where no sidewalk rises beside it, the carriageway's edge comes down to the ground.
        const TriangleInfo edge = info(material, object, SurfacePart::Curb);
        if (road.sidewalkLeftWidth <= 0) faces(left, line.elevation, 0.0f, level, edge, kind);
        if (road.sidewalkRightWidth <= 0) faces(std::vector<Vec2d>(right.rbegin(), right.rend()),
                                                std::vector<float>(line.elevation.rbegin(), line.elevation.rend()),
                                                0.0f, level, edge, kind);
        const std::vector<float> startLevel{line.elevation.front(), line.elevation.front()};
        const std::vector<float> endLevel{line.elevation.back(), line.elevation.back()};
        if (start.deadEnd) faces({start.left, start.right}, startLevel, 0.0f, level, edge, kind);
        if (end.deadEnd) faces({end.right, end.left}, endLevel, 0.0f, level, edge, kind);

        if (road.sidewalkLeftWidth > 0)
            meshSidewalk(line, left, half + road.sidewalkLeftWidth, start.leftOuter, end.leftOuter, !start.leftGoesOn,
                         !end.leftGoesOn, object);
        if (road.sidewalkRightWidth > 0)
            meshSidewalk(line, right, -(half + road.sidewalkRightWidth), start.rightOuter, end.rightOuter,
                         !start.rightGoesOn, !end.rightGoesOn, object);
    }

    /// One side's sidewalk along `inner` (the carriageway's edge) out to `offset` m from the centerline
    /// (negative: right): its top, the curb face, the outer face and, where it stops, an end face.
    void meshSidewalk(const TrimmedLine& line, const std::vector<Vec2d>& inner, double offset, Vec2d startOuter,
                      Vec2d endOuter, bool stopsAtStart, bool stopsAtEnd, uint32_t object) {
        std::vector<Vec2d> outer = offsetPolyline(line.points, offset);
        outer.front() = startOuter;
        outer.back() = endOuter;
        const TriangleInfo top = info(StreetMaterial::Sidewalk, object, SurfacePart::Sidewalk);
        const TriangleInfo curb = info(StreetMaterial::Curb, object, SurfacePart::Curb);
        for (size_t k = 0; k + 1 < inner.size(); ++k) {
            const float ea = kSidewalkLevel + line.elevation[k], eb = kSidewalkLevel + line.elevation[k + 1];
            quad(world(inner[k], ea), world(inner[k + 1], eb), world(outer[k + 1], eb), world(outer[k], ea), top,
                 "sidewalks");
        }
        faces(inner, line.elevation, kRoadLevel, kSidewalkLevel, curb, "sidewalks");
        faces(outer, line.elevation, 0.0f, kSidewalkLevel, curb, "sidewalks");
        const std::vector<float> startLevel{line.elevation.front(), line.elevation.front()};
        const std::vector<float> endLevel{line.elevation.back(), line.elevation.back()};
        if (stopsAtStart) faces({inner.front(), outer.front()}, startLevel, 0.0f, kSidewalkLevel, curb, "sidewalks");
        if (stopsAtEnd) faces({inner.back(), outer.back()}, endLevel, 0.0f, kSidewalkLevel, curb, "sidewalks");
        ++out_.counts["sidewalks"];
    }

    RoadSegment segment(const Road& road, uint32_t object, Vec2d a, Vec2d b, double distance, uint32_t markings,
                        bool stopAtStart, bool stopAtEnd) {
        RoadSegment s;
        const Vec2d d = b - a;
        const double l = length(d);
        s.start = {float(a.x), float(-a.y)};
        s.direction = {float(d.x / l), float(-d.y / l)};
        s.length = float(l);
        s.distance = float(distance);
        s.halfWidth = road.width * 0.5f;
        int forward = road.lanes - road.lanes / 2, backward = road.lanes / 2;
        if (road.oneway) forward = road.lanes, backward = 0;
        else if (road.lanesForward > 0 || road.lanesBackward > 0) {
            forward = road.lanesForward > 0 ? road.lanesForward : std::max(road.lanes - road.lanesBackward, 0);
            backward = road.lanesBackward > 0 ? road.lanesBackward : std::max(road.lanes - road.lanesForward, 0);
        }
        forward = std::clamp(forward, 0, 255);
        backward = std::clamp(backward, 0, 255);
        s.lanesForward = uint8_t(forward);
        s.lanesBackward = uint8_t(backward);
        // Forward lanes lie right of the line between the directions, backward ones left of it; the
        // other way round where traffic keeps left.
        const int lanes = std::max(forward + backward, 1);
        const float rightShare = 2.0f * float(forward) / float(lanes) - 1.0f;
        s.centreOffset = s.halfWidth * (options_.leftHandTraffic ? -rightShare : rightShare);
        s.markings = markings;
        if (markings != 0 && options_.leftHandTraffic) s.markings |= kMarkLeftHand;
        if (markings != 0) {
            if (stopAtStart) s.markings |= kMarkStopAtStart;
            if (stopAtEnd) s.markings |= kMarkStopAtEnd;
        }
        if (zebras_.count(PointKey(a))) {
            s.markings |= kMarkZebraAtStart;
            zebrasFound_.insert(PointKey(a));
        }
        if (zebras_.count(PointKey(b))) {
            s.markings |= kMarkZebraAtEnd;
            zebrasFound_.insert(PointKey(b));
        }
        s.object = object;
        s.paint = options_.firstMaterial + uint32_t(StreetMaterial::PaintWhite);
        return s;
    }

    void meshJunction(const JunctionShape& j) {
        const Road& road = roads_[j.road];
        const uint32_t object = firstObject_ + j.road;
        const StreetMaterial material = surfaceMaterial(road);
        const char* kind = j.path ? "sidewalks" : "junctions";
        const TriangleInfo top = info(material, object, j.path ? SurfacePart::Sidewalk : SurfacePart::Junction);
        const float level = j.path ? kPathLevel : kRoadLevel, height = level + j.elevation;
        for (const auto& [a, b, c] : triangulateRing(j.ring, folded_))
            triangle(world(j.ring[a], height), world(j.ring[b], height), world(j.ring[c], height), top, kind);
        const TriangleInfo edge = info(material, object, SurfacePart::Curb);
        for (const std::vector<Vec2d>& side : j.bareSides)
            faces(side, std::vector<float>(side.size(), j.elevation), 0.0f, level, edge, kind);
    }

    void meshCorner(const SidewalkCorner& c) {
        const uint32_t object = firstObject_ + c.road;
        strip(c.inner, c.outer, kSidewalkLevel + c.elevation, info(StreetMaterial::Sidewalk, object, SurfacePart::Sidewalk),
              "sidewalks");
        const TriangleInfo curb = info(StreetMaterial::Curb, object, SurfacePart::Curb);
        faces(c.inner, std::vector<float>(c.inner.size(), c.elevation), kRoadLevel, kSidewalkLevel, curb, "sidewalks");
        faces(c.outer, std::vector<float>(c.outer.size(), c.elevation), 0.0f, kSidewalkLevel, curb, "sidewalks");
    }

    const std::vector<Road>& roads_;
    const std::vector<std::vector<float>>& elevations_;
    const StreetOptions& options_;
    StreetMesh& out_;
    const uint32_t firstObject_;
    std::unordered_set<PointKey, PointKeyHash> zebras_, zebrasFound_;
    uint64_t roadsDrawn_ = 0, pathsDrawn_ = 0, folded_ = 0;
    std::map<const char*, size_t> trianglesOf_;   ///< by kind: the kinds are string literals of this file
};

} // namespace

void meshStreetNetwork(const CityModel& city, const std::vector<Road>& fitted,
                       const std::vector<std::vector<float>>& elevations, const StreetOptions& options,
                       StreetMesh& out) {
    NetworkMesher(city, fitted, elevations, options, out).run();
}

} // namespace urbis
