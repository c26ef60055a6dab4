#include "streets/bridge_mesher.h"

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

/// The deck's cross-section of a road: its carriageway and sidewalks, the top at the road's or the
/// sidewalk's level on each edge.
DeckShape deckOf(const Road& r) {
    DeckShape shape;
    shape.leftWidth = r.width * 0.5 + std::max(r.sidewalkLeftWidth, 0.0f);
    shape.rightWidth = r.width * 0.5 + std::max(r.sidewalkRightWidth, 0.0f);
    shape.leftLevel = r.sidewalkLeftWidth > 0 ? kSidewalkLevel : kRoadLevel;
    shape.rightLevel = r.sidewalkRightWidth > 0 ? kSidewalkLevel : kRoadLevel;
    return shape;
}

} // namespace

void meshBridges(const std::vector<Road>& roads, const std::vector<std::vector<float>>& elevations,
                 const StreetOptions& options, StreetMesh& out) {
    if (elevations.size() != roads.size()) {
        out.dropped["bridge_elevations_missing"] += uint64_t(std::count_if(roads.begin(), roads.end(), [](const Road& r) { return r.bridge; }));
        return;
    }
    PierObstacles obstacles;
    std::unordered_map<PointKey, int, PointKeyHash> bridgeEnds;  // bridge ways ending at a point
    std::vector<const std::vector<Vec2d>*> bridgeLines;
    std::vector<size_t> bridgeRoads;
    for (size_t i = 0; i < roads.size(); ++i) {
        const Road& r = roads[i];
        if (!atSurface(r) || !meshableLine(r.centerline) || elevations[i].size() != r.centerline.size()) continue;
        obstacles.add(r.centerline, r.width * 0.5, r.bridge ? r.layer : kGroundLevel);
        if (!r.bridge) continue;
        ++bridgeEnds[keyOf(r.centerline.front())];
        ++bridgeEnds[keyOf(r.centerline.back())];
        bridgeLines.push_back(&r.centerline);
        bridgeRoads.push_back(i);
    }
    const std::vector<double> chainStart = chainOffsets(bridgeLines);
    const uint32_t concrete = options.firstMaterial + uint32_t(StreetMaterial::BridgeConcrete);
    const uint32_t parapetMaterial = options.firstMaterial + uint32_t(StreetMaterial::Parapet);
    size_t triangles = 0;
    uint64_t bridges = 0;
    size_t next = 0;  // the next of bridgeRoads
    std::vector<BridgeWay> spanWays;
    for (size_t i = 0; i < roads.size(); ++i) {
        const Road& r = roads[i];
        const std::vector<float>& e = elevations[i];
        const bool isMeshed = next < bridgeRoads.size() && bridgeRoads[next] == i;
        if (r.bridge && !isMeshed) {
            ++out.dropped[atSurface(r) ? "bridge_degenerate" : "bridge_not_drawn"];
            continue;
        }
        const uint32_t object = options.firstObject + uint32_t(i);
        const TriangleInfo deck{concrete, object, uint32_t(SurfacePart::BridgeDeck)};
        const TriangleInfo parapet{parapetMaterial, object, uint32_t(SurfacePart::Parapet)};
        DeckShape shape = deckOf(r);
        if (isMeshed) {
            shape.closeStart = e.front() > 0 && bridgeEnds[keyOf(r.centerline.front())] == 1;
            shape.closeEnd = e.back() > 0 && bridgeEnds[keyOf(r.centerline.back())] == 1;
            triangles += meshDeck(r.centerline, e, shape, deck, parapet, out.mesh);
            spanWays.push_back({&r.centerline, &e, std::max(shape.leftWidth, shape.rightWidth) + kParapetThickness});
            const PierDeck pierDeck{chainStart[next], shape.leftWidth, shape.rightWidth,
                                    kRoadLevel - kDeckThickness, r.layer};
            triangles += meshPiers(r.centerline, e, pierDeck, obstacles,
                                   {concrete, object, uint32_t(SurfacePart::Pier)}, out.mesh);
            ++bridges;
            ++next;
            continue;
        }
        if (!atSurface(r) || !meshableLine(r.centerline) || e.size() != r.centerline.size()) continue;
        triangles += meshEmbankments(r.centerline, e, shape, deck, parapet, out.mesh);
    }
    for (BridgeSpan& span : bridgeSpans(spanWays)) out.bridgeSpans.push_back(std::move(span));
    out.objects = std::max(out.objects, uint32_t(roads.size()));
    out.counts["bridges"] += bridges;
    out.trianglesByKind["bridges"] += triangles;
}

} // namespace urbis
