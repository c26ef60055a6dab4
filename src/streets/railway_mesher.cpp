#include "streets/railway_mesher.h"

#include "scene/surface_part.h"
#include "streets/bridge_deck.h"
#include "streets/bridge_piers.h"
#include "streets/polyline.h"
#include "streets/road_elevation.h"
#include "streets/street_levels.h"
#include "streets/street_materials.h"

#include <algorithm>
#include <unordered_map>

namespace urbis {

namespace {

/// One rail `across` metres left of the centerline: a box on `base` (its sides and top), or for an
/// embedded rail just its top, a strip at `base`.
size_t addRail(TriangleMesh& mesh, const std::vector<Vec2d>& line, double across, const std::vector<float>& base,
               bool embedded, TriangleInfo info) {
    const std::vector<Vec2d> left = offsetPolyline(line, across + kRailWidth / 2);
    const std::vector<Vec2d> right = offsetPolyline(line, across - kRailWidth / 2);
    if (embedded) return addRibbon(mesh, left, base, right, base, info);
    const std::vector<float> top = raised(base, kRailHeight);
    return addRibbon(mesh, left, base, left, top, info) + addRibbon(mesh, right, base, right, top, info) +
           addRibbon(mesh, left, top, right, top, info);
}

/// The ballast bed: its top between ±halfTop at base + kBallastLevel, sides sloping to ±(halfTop +
/// kBallastSlopeReach) at base, and its ends closed where asked.
size_t addBallast(TriangleMesh& mesh, const std::vector<Vec2d>& line, double halfTop, const std::vector<float>& base,
                  bool closeStart, bool closeEnd, TriangleInfo info) {
    const std::vector<float> top = raised(base, kBallastLevel);
    const std::vector<Vec2d> topLeft = offsetPolyline(line, halfTop), topRight = offsetPolyline(line, -halfTop);
    const std::vector<Vec2d> toeLeft = offsetPolyline(line, halfTop + kBallastSlopeReach);
    const std::vector<Vec2d> toeRight = offsetPolyline(line, -halfTop - kBallastSlopeReach);
    size_t n = addRibbon(mesh, topLeft, top, topRight, top, info) + addRibbon(mesh, toeLeft, base, topLeft, top, info) +
               addRibbon(mesh, topRight, top, toeRight, base, info);
    for (size_t end : {size_t(0), line.size() - 1}) {
        if (!(end == 0 ? closeStart : closeEnd)) continue;
        n += addQuad(mesh, worldFromStreet(toeLeft[end], base[end]), worldFromStreet(topLeft[end], top[end]),
                     worldFromStreet(topRight[end], top[end]), worldFromStreet(toeRight[end], base[end]), info);
    }
    return n;
}

} // namespace

void meshRailways(const CityModel& city, const StreetOptions& options, StreetMesh& out) {
    const std::vector<Railway>& railways = city.railways;
    const std::vector<std::vector<float>> elevations = railwayElevations(railways);
    PierObstacles obstacles;
    for (const Road& r : city.roads)
        if (atSurface(r)) obstacles.add(r.centerline, r.width * 0.5, r.bridge ? r.layer : kGroundLevel);
    std::unordered_map<PointKey, int, PointKeyHash> ends;  // railways ending at a point
    std::vector<const std::vector<Vec2d>*> bridgeLines;
    std::vector<size_t> bridgeOf(railways.size(), 0);  // a bridge's index in bridgeLines
    for (size_t i = 0; i < railways.size(); ++i) {
        const Railway& r = railways[i];
        if (!atSurface(r) || !meshableLine(r.centerline)) continue;
        obstacles.add(r.centerline, kBallastHalfTop + kBallastSlopeReach, r.bridge ? r.layer : kGroundLevel);
        ++ends[keyOf(r.centerline.front())];
        ++ends[keyOf(r.centerline.back())];
        if (!r.bridge) continue;
        bridgeOf[i] = bridgeLines.size();
        bridgeLines.push_back(&r.centerline);
    }
    const std::vector<double> chainStart = chainOffsets(bridgeLines);
    const uint32_t material = options.firstMaterial;
    const uint32_t firstObject = options.firstObject + out.objects;  // after the parts meshed before
    size_t triangles = 0;
    uint64_t meshed = 0;
    std::vector<BridgeWay> spanWays;
    for (size_t i = 0; i < railways.size(); ++i) {
        const Railway& r = railways[i];
        if (!atSurface(r)) {
            ++out.dropped["railway_not_at_surface"];
            continue;
        }
        if (!meshableLine(r.centerline) || !(r.gauge > 0.3f && r.gauge < 3.0f)) {
            ++out.dropped["railway_degenerate"];
            continue;
        }
        const std::vector<float>& e = elevations[i];
        const uint32_t object = firstObject + uint32_t(i);
        const TriangleInfo concrete{material + uint32_t(StreetMaterial::BridgeConcrete), object,
                                    uint32_t(SurfacePart::BridgeDeck)};
        const TriangleInfo parapet{material + uint32_t(StreetMaterial::Parapet), object, uint32_t(SurfacePart::Parapet)};
        const TriangleInfo rail{material + uint32_t(StreetMaterial::RailSteel), object, uint32_t(SurfacePart::Rail)};
        const bool embedded = r.embedded || r.kind == RailKind::Tram;
        const double halfTop = std::max(kBallastHalfTop, double(r.gauge) / 2 + 0.8);
        // Embedded rails lie in the street's surface; a track on ballast carries its rails on the bed's top.
        const std::vector<float> railBase = raised(e, embedded ? kRoadLevel + kEmbeddedRailRise : kBallastLevel);
        if (!embedded)
            triangles += addBallast(out.mesh, r.centerline, halfTop, e, ends[keyOf(r.centerline.front())] == 1,
                                    ends[keyOf(r.centerline.back())] == 1,
                                    {material + uint32_t(StreetMaterial::Ballast), object, uint32_t(SurfacePart::Ballast)});
        for (double side : {-1.0, 1.0})
            triangles += addRail(out.mesh, r.centerline, side * (r.gauge + kRailWidth) / 2, railBase, embedded, rail);
        // A deck as wide as the bed's foot and its parapets; tops of its own, since no road covers it.
        DeckShape shape;
        shape.leftWidth = shape.rightWidth = halfTop + kBallastSlopeReach + kParapetThickness;
        shape.leftLevel = shape.rightLevel = kRoadLevel;
        shape.top = true;
        if (r.bridge) {
            shape.closeStart = e.front() > 0 && ends[keyOf(r.centerline.front())] == 1;
            shape.closeEnd = e.back() > 0 && ends[keyOf(r.centerline.back())] == 1;
            triangles += meshDeck(r.centerline, e, shape, concrete, parapet, out.mesh);
            spanWays.push_back({&r.centerline, &e, shape.leftWidth + kParapetThickness});
            const PierDeck deck{chainStart[bridgeOf[i]], shape.leftWidth, shape.rightWidth, kRoadLevel - kDeckThickness, r.layer};
            triangles += meshPiers(r.centerline, e, deck, obstacles,
                                   {concrete.material, object, uint32_t(SurfacePart::Pier)}, out.mesh);
        } else {
            triangles += meshEmbankments(r.centerline, e, shape, concrete, parapet, out.mesh);
        }
        ++meshed;
    }
    for (BridgeSpan& span : bridgeSpans(spanWays)) out.bridgeSpans.push_back(std::move(span));
    out.objects += uint32_t(railways.size());
    out.counts["railways"] += meshed;
    out.trianglesByKind["railways"] += triangles;
}

} // namespace urbis
