#include "citygen/roof_mesher.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

namespace urbis {

namespace {

constexpr double kDefaultPitchDegrees = 40.0;
constexpr double kSkillionPitchDegrees = 15.0;
constexpr double kParapetMinWall = 8.0;      ///< m of building under a flat roof that gets a parapet
constexpr double kParapetThickness = 0.3;    ///< m
constexpr int kRoundSegments = 16;           ///< segments of a round (barrel) roof's half ellipse
constexpr int kDomeRings = 8;                ///< rings of a dome from the eaves to the apex

/// The minimum-area rectangle around a ring among those with a side along one of its edges.
struct OrientedBox {
    Vec2d longAxis{1, 0};
    double longSide = 0, shortSide = 0;
};

OrientedBox orientedBox(const Ring& ring) {
    OrientedBox best;
    double bestArea = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < ring.size(); ++i) {
        const Vec2d a = ring[i], b = ring[(i + 1) % ring.size()];
        const double length = std::hypot(b.x - a.x, b.y - a.y);
        if (length == 0) continue;
        const Vec2d u{(b.x - a.x) / length, (b.y - a.y) / length}, v{-u.y, u.x};
        double ulo = INFINITY, uhi = -INFINITY, vlo = INFINITY, vhi = -INFINITY;
        for (const Vec2d& p : ring) {
            const double pu = p.x * u.x + p.y * u.y, pv = p.x * v.x + p.y * v.y;
            ulo = std::min(ulo, pu), uhi = std::max(uhi, pu), vlo = std::min(vlo, pv), vhi = std::max(vhi, pv);
        }
        const double du = uhi - ulo, dv = vhi - vlo;
        if (du * dv >= bestArea) continue;
        bestArea = du * dv;
        best = du >= dv ? OrientedBox{u, du, dv} : OrientedBox{v, dv, du};
    }
    return best;
}

/// Whether a counter-clockwise ring turns left (or goes straight) at every vertex.
bool isConvex(const Ring& ring) {
    for (size_t i = 0; i < ring.size(); ++i) {
        const Vec2d a = ring[i], b = ring[(i + 1) % ring.size()], c = ring[(i + 2) % ring.size()];
        const double cross = (b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x);
        if (cross < -1e-9 * (std::abs(b.x - a.x) + std::abs(b.y - a.y)) * (std::abs(c.x - b.x) + std::abs(c.y - b.y)))
            return false;
    }
    return true;
}

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

/// Height profile across the ridge from the footprint's extent [lo, hi] along the slope direction.
RoofProfile ridgeProfile(RoofShape shape, double lo, double hi, double height) {
    const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
    switch (shape) {
    case RoofShape::Skillion: return {{lo, hi}, {height, 0}};  // downhill toward +s
    case RoofShape::Gambrel:  // steep lower quarter rising 60%, then shallow to the ridge
        return {{lo, lo + 0.25 * half, mid, hi - 0.25 * half, hi}, {0, 0.6 * height, height, 0.6 * height, 0}};
    case RoofShape::Round: {  // half ellipse
        RoofProfile p;
        for (int k = 0; k <= kRoundSegments; ++k) {
            const double phi = std::numbers::pi * k / kRoundSegments;
            p.s.push_back(k == 0 ? lo : k == kRoundSegments ? hi : mid - half * std::cos(phi));
            p.h.push_back(k == 0 || k == kRoundSegments ? 0.0 : height * std::sin(phi));
        }
        return p;
    }
    default: return {{lo, mid, hi}, {0, height, 0}};  // gabled
    }
}

std::vector<RevolutionStep> revolutionSteps(RoofShape shape, double height) {
    std::vector<RevolutionStep> steps;
    if (shape == RoofShape::Onion) {  // bulges to 1.25x the drum, then a concave spire
        static constexpr RevolutionStep kOnion[] = {{1.0, 0.0}, {1.15, 0.08}, {1.25, 0.2}, {1.22, 0.32}, {1.08, 0.44},
                                                    {0.8, 0.56}, {0.5, 0.68}, {0.27, 0.8}, {0.12, 0.9}, {0.0, 1.0}};
        for (const RevolutionStep& s : kOnion) steps.push_back({s.scale, s.height * height});
        return steps;
    }
    for (int k = 0; k <= kDomeRings; ++k) {  // quarter ellipse
        const double phi = 0.5 * std::numbers::pi * k / kDomeRings;
        steps.push_back({k == kDomeRings ? 0.0 : std::cos(phi), k == kDomeRings ? height : height * std::sin(phi)});
    }
    return steps;
}

} // namespace

double roofHeightOf(const Building& building, RoofShape shape, double depth, double halfSpan) {
    const double room = std::max(0.0, double(building.height - building.minHeight));
    if (shape == RoofShape::Flat || shape == RoofShape::Unknown) return 0.0;
    if (building.roofHeight > 0) return std::min(double(building.roofHeight), room);
    double span = halfSpan, pitch = kDefaultPitchDegrees;
    switch (shape) {
    case RoofShape::Hipped: case RoofShape::Pyramidal: case RoofShape::Mansard: span = depth; break;
    case RoofShape::Skillion: span = 2 * halfSpan, pitch = kSkillionPitchDegrees; break;
    case RoofShape::Dome: span = depth, pitch = 45.0; break;
    case RoofShape::Onion: span = 2.5 * depth, pitch = 45.0; break;
    default: break;
    }
    if (building.roofAngle > 0 && building.roofAngle < 90) return std::min(room, span * std::tan(radians(building.roofAngle)));
    return std::min(0.5 * room, span * std::tan(radians(pitch)));
}

RoofResult meshRoof(const Building& building, const FootprintTriangles& footprint, TriangleInfo roofInfo,
                    TriangleInfo wallInfo, TriangleMesh& mesh) {
    RoofResult result;
    const Polygon& polygon = building.footprint;
    const OrientedBox box = orientedBox(polygon.outer);
    const bool convex = polygon.holes.empty() && isConvex(polygon.outer);
    RoofShape shape = building.roofShape;
    if (shape == RoofShape::Unknown) {
        result.fallbacks.push_back("unknown_shape");
        shape = RoofShape::Flat;
    }
    if ((shape == RoofShape::Dome || shape == RoofShape::Onion) && !(convex && box.longSide <= 1.5 * box.shortSide)) {
        result.fallbacks.push_back("dome_not_round");
        shape = RoofShape::Hipped;
    }
    const bool parapet = shape == RoofShape::Flat && building.height - building.minHeight >= kParapetMinWall;
    // A gabled roof over wings (not convex) gets a ridge and gables per wing, unless a tag sets one
    // ridge direction for the whole roof.
    const bool gablesPerWing = shape == RoofShape::Gabled && !convex && building.roofDirection < 0 && !building.roofAcross;
    std::optional<StraightSkeleton> skeleton;
    if (parapet || gablesPerWing || shape == RoofShape::Hipped || shape == RoofShape::Mansard ||
        (shape == RoofShape::Pyramidal && !convex)) {
        skeleton = interiorStraightSkeleton(polygon);
        if (!skeleton && !gablesPerWing) {  // hipped or mansard -> pyramidal (convex) -> flat; parapet -> plain flat
            result.fallbacks.push_back("skeleton_failed");
            if (shape != RoofShape::Flat) shape = convex && shape != RoofShape::Pyramidal ? RoofShape::Pyramidal : RoofShape::Flat;
        }
    }

    // The slope direction: roof:direction, else across the ridge, which runs along the longer side
    // of the oriented bounding box (across it for roof:orientation=across).
    const Vec2d across = building.roofDirection >= 0
                             ? Vec2d{std::sin(radians(building.roofDirection)), std::cos(radians(building.roofDirection))}
                         : building.roofAcross ? box.longAxis
                                               : Vec2d{-box.longAxis.y, box.longAxis.x};
    double lo = INFINITY, hi = -INFINITY;
    for (const Vec2d& p : polygon.outer) lo = std::min(lo, p.x * across.x + p.y * across.y), hi = std::max(hi, p.x * across.x + p.y * across.y);
    const double depth = skeleton ? skeleton->maxTime : 0.5 * box.shortSide;
    const double height = roofHeightOf(building, shape, depth, skeleton && gablesPerWing ? depth : 0.5 * (hi - lo));

    RoofSink sink{mesh, roofInfo, wallInfo, building.height - height};
    bool done = true;
    switch (shape) {
    case RoofShape::Flat: {
        const double parapetHeight = 0.8 + 0.4 * double(building.seed) * 0x1p-32;
        if (skeleton && skeleton->maxTime > 2 * kParapetThickness) {
            done = meshParapetRoof(*skeleton, parapetHeight, kParapetThickness, sink, result.parapetBands);
            if (done) {
                result.parapetHeight = parapetHeight;
                result.parapetThickness = kParapetThickness;
            }
        } else
            meshFlatRoof(footprint, sink);
        break;
    }
    case RoofShape::Gabled:
        if (gablesPerWing) {
            if (skeleton && meshGabledSkeletonRoof(*skeleton, {{0, depth}, {0, height}}, sink)) break;
            result.fallbacks.push_back("gables_one_ridge");
        }
        [[fallthrough]];  // one ridge across the footprint
    case RoofShape::Skillion: case RoofShape::Gambrel: case RoofShape::Round:
        meshRidgeRoof(polygon, footprint, across, ridgeProfile(shape, lo, hi, height), sink);
        break;
    case RoofShape::Mansard:  // steep lower quarter rising 65%, then shallow
        done = meshSkeletonRoof(*skeleton, {{0, 0.25 * depth, depth}, {0, 0.65 * height, height}}, sink);
        break;
    case RoofShape::Pyramidal:
        if (convex) meshPyramidRoof(polygon.outer, height, sink);
        else done = meshSkeletonRoof(*skeleton, {{0, depth}, {0, height}}, sink);
        break;
    case RoofShape::Dome: case RoofShape::Onion:
        meshRevolvedRoof(polygon.outer, revolutionSteps(shape, height), sink);
        break;
    default:  // hipped
        done = meshSkeletonRoof(*skeleton, {{0, depth}, {0, height}}, sink);
        break;
    }
    if (!done) {  // nothing was emitted
        result.fallbacks.push_back(shape == RoofShape::Flat ? "parapet_failed" : "skeleton_face_failed");
        sink.base = building.height;
        meshFlatRoof(footprint, sink);
    }
    result.wallTop = sink.base;
    result.roofTriangles = sink.roofTriangles;
    result.wallTriangles = sink.wallTriangles;
    return result;
}

} // namespace urbis
