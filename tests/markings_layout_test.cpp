// Lane markings against their analytic layout (geometry/road_markings.h): a straight road quad of
// Road triangles over one RoadSegment, traced with vertical rays on fine lines and grids, so every
// check goes through the triangle kind's surface as a render does. Each test names the convention it
// checks: dash period and duty, solid and doubled centre lines, yellow, lane dividers, edge lines,
// stop lines and zebras; uv on a rotated segment; dashes running on across two segments.
#include "geometry/road_markings.h"
#include "geometry/scene_intersect.h"
#include "scene/scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace urbis;
using namespace urbis::marking;

namespace {

constexpr uint32_t kAsphalt = 0, kWhite = 1, kYellow = 2;
constexpr uint32_t kRoadObject = 41;

/// A segment along +x from (x0, 0): a two-lane road 7 m wide unless changed.
RoadSegment straightSegment(uint32_t markings, float length = 60.0f, float x0 = 0.0f, float distance = 0.0f) {
    RoadSegment s;
    s.start = {x0, 0.0f};
    s.direction = {1.0f, 0.0f};
    s.length = length;
    s.distance = distance;
    s.halfWidth = 3.5f;
    s.markings = markings;
    s.object = kRoadObject;
    s.paint = kWhite;
    return s;
}

/// World (x, z) of a point `along` and `across` (left positive) of a segment.
Vec2f worldOf(const RoadSegment& s, float along, float across) {
    const Vec2f left{s.direction.y, -s.direction.x};
    return {s.start.x + along * s.direction.x + across * left.x, s.start.y + along * s.direction.y + across * left.y};
}

/// Each segment's carriageway as two Road triangles (object: the segment's index) over the ground.
Scene roadScene(const std::vector<RoadSegment>& segments) {
    TriangleMesh mesh;
    for (uint32_t i = 0; i < segments.size(); ++i) {
        const RoadSegment& s = segments[i];
        const Vec2f a = worldOf(s, 0, -s.halfWidth), b = worldOf(s, s.length, -s.halfWidth);
        const Vec2f c = worldOf(s, s.length, s.halfWidth), d = worldOf(s, 0, s.halfWidth);
        const TriangleInfo info{kAsphalt, i, uint32_t(SurfacePart::Road)};
        mesh.add({{a.x, 0, a.y}, {b.x, 0, b.y}, {c.x, 0, c.y}}, info);
        mesh.add({{a.x, 0, a.y}, {c.x, 0, c.y}, {d.x, 0, d.y}}, info);
    }
    Scene scene = Scene::build({.mesh = mesh, .materials = std::vector<Material>(3)});
    scene.roadSegments = segments;
    return scene;
}

/// The hit of a vertical ray down onto world (x, z).
SurfaceHit traceDown(const Scene& scene, Vec2f xz) {
    return intersectScene(scene.view(), Ray{{xz.x, 10.0f, xz.y}, {0.0f, -1.0f, 0.0f}});
}

/// The material at a point of segment `index` of the scene.
uint32_t materialAt(const Scene& scene, float along, float across, uint32_t index = 0) {
    const SurfaceHit h = traceDown(scene, worldOf(scene.roadSegments[index], along, across));
    EXPECT_TRUE(h.valid() && h.part == SurfacePart::Road) << "along " << along << " across " << across;
    return h.material;
}

/// A stretch of samples of one material along a line of samples.
struct Stretch {
    uint32_t material;
    float from, to;   ///< first and last sample's coordinate
};

constexpr float kStep = 0.01f;

/// Runs of equal material at samples kStep apart over [from, to], half a step in from each end (an
/// edge of the road's quad is no sample), of `coordinate`, the other held fixed.
template <typename MaterialAt>
std::vector<Stretch> runs(float from, float to, MaterialAt&& materialAtCoordinate) {
    std::vector<Stretch> out;
    const int samples = int(std::lround((to - from) / kStep));
    for (int i = 0; i < samples; ++i) {
        const float x = from + (float(i) + 0.5f) * kStep;
        const uint32_t m = materialAtCoordinate(x);
        if (out.empty() || out.back().material != m) out.push_back({m, x, x});
        else out.back().to = x;
    }
    return out;
}

std::vector<Stretch> runsAlong(const Scene& scene, float across, float from, float to) {
    return runs(from, to, [&](float along) { return materialAt(scene, along, across); });
}

std::vector<Stretch> runsAcross(const Scene& scene, float along, float from, float to) {
    return runs(from, to, [&](float across) { return materialAt(scene, along, across); });
}

/// The painted runs of a line, of the given paint.
std::vector<Stretch> painted(const std::vector<Stretch>& line, uint32_t paint) {
    std::vector<Stretch> out;
    for (const Stretch& r : line)
        if (r.material == paint) out.push_back(r);
    return out;
}

/// A run's extent; samples are kStep apart, so each edge is known to kStep.
float extent(const Stretch& r) { return r.to - r.from + kStep; }

/// Checks a dashed line's period and duty along `across` over the whole segment.
void expectDashes(const Scene& scene, float across, uint32_t paint, float gap) {
    const std::vector<Stretch> dashes = painted(runsAlong(scene, across, 0.0f, scene.roadSegments[0].length), paint);
    ASSERT_GE(dashes.size(), 4u);
    for (size_t i = 0; i < dashes.size(); ++i) {
        EXPECT_NEAR(dashes[i].from, float(i) * (kDashLength + gap), 2 * kStep) << "dash " << i;
        if (i + 1 < dashes.size()) {
            EXPECT_NEAR(extent(dashes[i]), kDashLength, 2 * kStep) << "dash " << i;
        }
    }
}

} // namespace

TEST(MarkingsLayout, EuropeanCentreLineDashesThreeMetresEverySixAndIsNarrow) {
    const Scene scene = roadScene({straightSegment(kMarkCentreLine | kMarkCentreDashed)});
    expectDashes(scene, 0.0f, kWhite, 6.0f);   // 3 m / 6 m
    // Across a dash: one white run of the line's width, centred on the centre line.
    const std::vector<Stretch> across = painted(runsAcross(scene, 1.5f, -3.5f, 3.5f), kWhite);
    ASSERT_EQ(across.size(), 1u);
    EXPECT_NEAR(0.5f * (across[0].from + across[0].to), 0.0f, kStep);
    EXPECT_NEAR(extent(across[0]), kLineWidth, 2 * kStep);
}

TEST(MarkingsLayout, CentreLineIsSolidWhereOvertakingIsForbidden) {
    const Scene scene = roadScene({straightSegment(kMarkCentreLine)});
    const std::vector<Stretch> line = runsAlong(scene, 0.0f, 0.0f, 60.0f);
    ASSERT_EQ(line.size(), 1u);
    EXPECT_EQ(line[0].material, kWhite);
    EXPECT_EQ(materialAt(scene, 30.0f, 0.2f), kAsphalt);
}

TEST(MarkingsLayout, CentreLineFollowsItsOffset) {
    RoadSegment s = straightSegment(kMarkCentreLine);
    s.centreOffset = 1.0f;
    const Scene scene = roadScene({s});
    EXPECT_EQ(materialAt(scene, 20.0f, 1.0f), kWhite);
    EXPECT_EQ(materialAt(scene, 20.0f, 0.0f), kAsphalt);
}

TEST(MarkingsLayout, AmericanNoPassingCentreLineIsDoubleYellow) {
    const Scene scene = roadScene({straightSegment(kMarkCentreLine | kMarkCentreYellow | kMarkAmerican)});
    const std::vector<Stretch> line = runsAcross(scene, 10.0f, -3.5f, 3.5f);
    const std::vector<Stretch> yellow = painted(line, kYellow);
    ASSERT_EQ(yellow.size(), 2u);
    EXPECT_TRUE(painted(line, kWhite).empty());
    const float offset = 0.5f * (kDoubleLineGap + kLineWidth);
    EXPECT_NEAR(0.5f * (yellow[0].from + yellow[0].to), -offset, kStep);
    EXPECT_NEAR(0.5f * (yellow[1].from + yellow[1].to), offset, kStep);
    EXPECT_NEAR(yellow[1].from - yellow[0].to - kStep, kDoubleLineGap, 2 * kStep);
    EXPECT_EQ(materialAt(scene, 10.0f, 0.0f), kAsphalt);   // the gap between the two lines
}

TEST(MarkingsLayout, AmericanDashedCentreLineIsSingleYellowThreeMetresEveryNine) {
    const Scene scene =
        roadScene({straightSegment(kMarkCentreLine | kMarkCentreDashed | kMarkCentreYellow | kMarkAmerican)});
    expectDashes(scene, 0.0f, kYellow, 9.0f);   // 10 ft / 30 ft
}

TEST(MarkingsLayout, LaneDividersOfAFourLaneRoadAreDashedWhiteBetweenLanesOfOneDirection) {
    RoadSegment s = straightSegment(kMarkCentreLine | kMarkLaneDividers);
    s.halfWidth = 7.0f;
    s.lanesForward = s.lanesBackward = 2;
    const Scene scene = roadScene({s});
    // Across a dash: the dividers halfway across each direction's 7 m, the solid centre line between.
    const std::vector<Stretch> across = painted(runsAcross(scene, 1.5f, -7.0f, 7.0f), kWhite);
    ASSERT_EQ(across.size(), 3u);
    const float centres[] = {-3.5f, 0.0f, 3.5f};
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(0.5f * (across[size_t(i)].from + across[size_t(i)].to), centres[i], kStep);
        EXPECT_NEAR(extent(across[size_t(i)]), kLineWidth, 2 * kStep);
    }
    expectDashes(scene, 3.5f, kWhite, kDashGapEurope);
    expectDashes(scene, -3.5f, kWhite, kDashGapEurope);
}

TEST(MarkingsLayout, OneWayRoadDividesItsLanesAcrossTheWholeWidth) {
    RoadSegment s = straightSegment(kMarkLaneDividers);
    s.halfWidth = 5.25f;
    s.centreOffset = s.halfWidth;
    s.lanesForward = 3;
    s.lanesBackward = 0;
    const Scene scene = roadScene({s});
    const std::vector<Stretch> across = painted(runsAcross(scene, 1.5f, -5.25f, 5.25f), kWhite);
    ASSERT_EQ(across.size(), 2u);
    EXPECT_NEAR(0.5f * (across[0].from + across[0].to), -1.75f, kStep);
    EXPECT_NEAR(0.5f * (across[1].from + across[1].to), 1.75f, kStep);
}

TEST(MarkingsLayout, EdgeLinesAreSolidWhiteInsetFromBothEdges) {
    const Scene scene = roadScene({straightSegment(kMarkEdgeLines)});
    const std::vector<Stretch> across = painted(runsAcross(scene, 7.0f, -3.5f, 3.5f), kWhite);
    ASSERT_EQ(across.size(), 2u);
    EXPECT_NEAR(across[0].from, -3.5f + kEdgeLineInset, 2 * kStep);
    EXPECT_NEAR(extent(across[0]), kEdgeLineWidth, 2 * kStep);
    EXPECT_NEAR(across[1].to, 3.5f - kEdgeLineInset, 2 * kStep);
    EXPECT_NEAR(extent(across[1]), kEdgeLineWidth, 2 * kStep);
    const float line = 3.5f - kEdgeLineInset - 0.5f * kEdgeLineWidth;
    EXPECT_EQ(runsAlong(scene, line, 0.0f, 60.0f).size(), 1u);
    EXPECT_EQ(runsAlong(scene, -line, 0.0f, 60.0f).size(), 1u);
}

TEST(MarkingsLayout, AmericanOneWayLeftEdgeLineIsYellow) {
    RoadSegment s = straightSegment(kMarkEdgeLines | kMarkAmerican);
    s.centreOffset = s.halfWidth;
    s.lanesBackward = 0;
    const Scene scene = roadScene({s});
    const float line = 3.5f - kEdgeLineInset - 0.5f * kEdgeLineWidth;
    EXPECT_EQ(materialAt(scene, 5.0f, line), kYellow);
    EXPECT_EQ(materialAt(scene, 5.0f, -line), kWhite);
}

TEST(MarkingsLayout, StopLineCrossesTheArrivingLanesSetBackFromTheEnd) {
    const Scene scene = roadScene({straightSegment(kMarkStopAtEnd, 30.0f)});
    // Along the forward lanes (right of the centre line): one bar ending kStopLineSetback before the end.
    const std::vector<Stretch> along = painted(runsAlong(scene, -1.75f, 20.0f, 30.0f), kWhite);
    ASSERT_EQ(along.size(), 1u);
    EXPECT_NEAR(along[0].to, 30.0f - kStopLineSetback, 2 * kStep);
    EXPECT_NEAR(extent(along[0]), kStopLineWidth, 2 * kStep);
    // Across it: from the right edge to the centre line, not over the lanes leaving.
    const float middle = 30.0f - kStopLineSetback - 0.5f * kStopLineWidth;
    const std::vector<Stretch> across = painted(runsAcross(scene, middle, -3.5f, 3.5f), kWhite);
    ASSERT_EQ(across.size(), 1u);
    EXPECT_NEAR(across[0].from, -3.5f, 2 * kStep);
    EXPECT_NEAR(across[0].to, 0.0f, 2 * kStep);
    EXPECT_TRUE(painted(runsAlong(scene, -1.75f, 0.0f, 20.0f), kWhite).empty());
}

TEST(MarkingsLayout, StopLineAtTheStartCrossesTheBackwardLanes) {
    const Scene scene = roadScene({straightSegment(kMarkStopAtStart, 30.0f)});
    const std::vector<Stretch> along = painted(runsAlong(scene, 1.75f, 0.0f, 10.0f), kWhite);
    ASSERT_EQ(along.size(), 1u);
    EXPECT_NEAR(along[0].from, kStopLineSetback, 2 * kStep);
    const std::vector<Stretch> across = painted(runsAcross(scene, kStopLineSetback + 0.2f, -3.5f, 3.5f), kWhite);
    ASSERT_EQ(across.size(), 1u);
    EXPECT_NEAR(across[0].from, 0.0f, 2 * kStep);
    EXPECT_NEAR(across[0].to, 3.5f, 2 * kStep);
}

TEST(MarkingsLayout, ZebraStripesRunAlongTheRoadHalfABandOnEachSegment) {
    RoadSegment s = straightSegment(kMarkZebraAtEnd | kMarkCentreLine, 30.0f);
    s.centreOffset = 0.5f;   // in a gap between two stripes
    const Scene scene = roadScene({s});
    // Across the band: stripes 0.5 m wide every metre, one on the centreline, seven over 7 m.
    const std::vector<Stretch> across = painted(runsAcross(scene, 29.0f, -3.5f, 3.5f), kWhite);
    ASSERT_EQ(across.size(), 7u);
    for (size_t i = 0; i < across.size(); ++i) {
        EXPECT_NEAR(0.5f * (across[i].from + across[i].to), float(i) - 3.0f, kStep) << "stripe " << i;
        EXPECT_NEAR(extent(across[i]), kZebraStripeWidth, 2 * kStep) << "stripe " << i;
    }
    // Along a stripe: painted from half a band before the end to the end, asphalt before.
    const std::vector<Stretch> stripe = runsAlong(scene, 1.0f, 20.0f, 30.0f);
    ASSERT_EQ(stripe.size(), 2u);
    EXPECT_NEAR(stripe[1].from, 30.0f - 0.5f * kZebraBand, 2 * kStep);
    EXPECT_NEAR(stripe[1].to, 30.0f, 2 * kStep);
    EXPECT_EQ(stripe[1].material, kWhite);
    // The centre line runs up to the band, not through it.
    const std::vector<Stretch> centre = runsAlong(scene, 0.5f, 20.0f, 30.0f);
    ASSERT_EQ(centre.size(), 2u);
    EXPECT_EQ(centre[0].material, kWhite);
    EXPECT_NEAR(centre[1].from, 30.0f - 0.5f * kZebraBand, 2 * kStep);
    EXPECT_EQ(centre[1].material, kAsphalt);
}

TEST(MarkingsLayout, StopLineStandsBehindAZebra) {
    const Scene scene = roadScene({straightSegment(kMarkZebraAtEnd | kMarkStopAtEnd, 30.0f)});
    const std::vector<Stretch> along = painted(runsAlong(scene, -2.0f, 20.0f, 30.0f), kWhite);
    ASSERT_EQ(along.size(), 2u);   // the stop line, then the stripe centred 2 m right
    EXPECT_NEAR(along[0].to, 30.0f - 0.5f * kZebraBand - kStopLineSetback, 2 * kStep);
    EXPECT_NEAR(extent(along[0]), kStopLineWidth, 2 * kStep);
}

TEST(MarkingsLayout, NothingIsPaintedWithoutMarkings) {
    const Scene scene = roadScene({straightSegment(0)});
    for (float along = 0.05f; along < 60.0f; along += 0.25f)
        for (float across = -3.45f; across < 3.5f; across += 0.05f)
            ASSERT_EQ(materialAt(scene, along, across), kAsphalt) << along << ", " << across;
}

TEST(MarkingsLayout, NothingIsPaintedBeyondTheSegmentOrTheCarriageway) {
    const uint32_t everything = kMarkCentreLine | kMarkLaneDividers | kMarkEdgeLines | kMarkStopAtStart |
                                kMarkStopAtEnd | kMarkZebraAtStart | kMarkZebraAtEnd;
    const RoadSegment s = straightSegment(everything, 30.0f);
    EXPECT_EQ(roadPaintAt(s, 0.0f, 0.0f), kWhitePaint);   // a zebra stripe on the centreline
    EXPECT_EQ(roadPaintAt(s, -0.01f, 0.0f), kNoPaint);
    EXPECT_EQ(roadPaintAt(s, 30.01f, 0.0f), kNoPaint);
    EXPECT_EQ(roadPaintAt(s, 15.0f, 0.0f), kWhitePaint);  // the solid centre line
    EXPECT_EQ(roadPaintAt(s, 15.0f, 3.51f), kNoPaint);
    EXPECT_EQ(roadPaintAt(s, 15.0f, -3.51f), kNoPaint);
}

TEST(MarkingsLayout, UvIsDistanceAlongAndAcrossOnARotatedSegment) {
    RoadSegment s = straightSegment(kMarkCentreLine, 40.0f, 0.0f, 125.0f);
    const float angle = 0.6f;
    s.start = {-12.0f, 31.0f};
    s.direction = {std::cos(angle), std::sin(angle)};
    const Scene scene = roadScene({s});
    for (float along : {0.5f, 7.25f, 21.0f, 39.5f})
        for (float across : {-3.2f, -1.0f, 0.0f, 0.4f, 2.9f}) {
            const SurfaceHit h = traceDown(scene, worldOf(s, along, across));
            ASSERT_TRUE(h.valid());
            EXPECT_NEAR(h.uv.x, 125.0f + along, 1e-3f);
            EXPECT_NEAR(h.uv.y, across, 1e-3f);
            EXPECT_EQ(h.object, kRoadObject);
            EXPECT_EQ(h.material, across == 0.0f ? kWhite : kAsphalt);
        }
    // The left of direction is positive: with z south, heading east (+x) the left is north (-z).
    const RoadSegment east = straightSegment(0);
    EXPECT_NEAR(roadCoordinates(east, 3.0f, -2.0f).y, 2.0f, 1e-6f);
}

TEST(MarkingsLayout, TracedPaintIsTheMarkingFunctionsOnARotatedGrid) {
    RoadSegment s = straightSegment(kMarkCentreLine | kMarkCentreDashed | kMarkLaneDividers | kMarkEdgeLines |
                                        kMarkStopAtStart | kMarkStopAtEnd | kMarkZebraAtStart,
                                    25.0f, 0.0f, 4.0f);
    s.start = {3.0f, -8.0f};
    s.direction = {-0.6f, 0.8f};
    s.halfWidth = 7.0f;
    s.lanesForward = s.lanesBackward = 2;
    const Scene scene = roadScene({s});
    size_t paintedPoints = 0, points = 0;
    for (float along = 0.03f; along < 25.0f; along += 0.07f)
        for (float across = -6.97f; across < 7.0f; across += 0.05f) {
            const uint32_t expected = roadPaintAt(s, along, across);
            // Points within a float's rounding of a line's edge may fall either side once rotated.
            if (roadPaintAt(s, along + 1e-3f, across) != expected || roadPaintAt(s, along - 1e-3f, across) != expected ||
                roadPaintAt(s, along, across + 1e-3f) != expected || roadPaintAt(s, along, across - 1e-3f) != expected)
                continue;
            ++points;
            paintedPoints += expected != kNoPaint;
            ASSERT_EQ(materialAt(scene, along, across), expected == kNoPaint ? kAsphalt : kWhite + expected - 1)
                << along << ", " << across;
        }
    EXPECT_GT(points, 90000u);
    EXPECT_GT(paintedPoints, 3000u);   // every kind of line is in the grid
}

TEST(MarkingsLayout, DashesRunOnAcrossTwoSegments) {
    // 10 m then 20 m: the dash at 9..12 m of the road crosses the join.
    const uint32_t dashed = kMarkCentreLine | kMarkCentreDashed;
    const Scene scene = roadScene({straightSegment(dashed, 10.0f), straightSegment(dashed, 20.0f, 10.0f, 10.0f)});
    std::vector<Stretch> line = runs(0.0f, 30.0f, [&](float x) { return traceDown(scene, {x, 0.0f}).material; });
    line = painted(line, kWhite);
    ASSERT_EQ(line.size(), 4u);
    for (size_t i = 0; i < line.size(); ++i) {
        EXPECT_NEAR(line[i].from, 9.0f * float(i), 2 * kStep) << "dash " << i;
        EXPECT_NEAR(extent(line[i]), kDashLength, 2 * kStep) << "dash " << i;
    }
}

TEST(MarkingsLayout, LeftHandTrafficMirrorsTheStopLines) {
    // Traffic keeping left arrives at the end on the left half and at the start on the right half.
    const Scene scene = roadScene({straightSegment(kMarkStopAtEnd | kMarkStopAtStart | kMarkLeftHand, 30.0f)});
    const float middleEnd = 30.0f - kStopLineSetback - 0.5f * kStopLineWidth;
    const std::vector<Stretch> atEnd = painted(runsAcross(scene, middleEnd, -3.5f, 3.5f), kWhite);
    ASSERT_EQ(atEnd.size(), 1u);
    EXPECT_NEAR(atEnd[0].from, 0.0f, 2 * kStep);
    EXPECT_NEAR(atEnd[0].to, 3.5f, 2 * kStep);
    const std::vector<Stretch> atStart = painted(runsAcross(scene, kStopLineSetback + 0.2f, -3.5f, 3.5f), kWhite);
    ASSERT_EQ(atStart.size(), 1u);
    EXPECT_NEAR(atStart[0].from, -3.5f, 2 * kStep);
    EXPECT_NEAR(atStart[0].to, 0.0f, 2 * kStep);
}

TEST(MarkingsLayout, LeftHandTrafficMirrorsUnevenLanesAndTheOneWayYellowEdge) {
    // Two lanes forward, one back, on a 10.5 m road: the dividers lie among the forward lanes, on the left.
    RoadSegment s = straightSegment(kMarkCentreLine | kMarkLaneDividers | kMarkLeftHand);
    s.halfWidth = 5.25f;
    s.lanesForward = 2;
    s.lanesBackward = 1;
    s.centreOffset = -1.75f;   // the forward share (7 m) left of the centre line
    const Scene scene = roadScene({s});
    const std::vector<Stretch> across = painted(runsAcross(scene, 1.5f, -5.25f, 5.25f), kWhite);
    ASSERT_EQ(across.size(), 2u);
    EXPECT_NEAR(0.5f * (across[0].from + across[0].to), -1.75f, kStep);   // the centre line
    EXPECT_NEAR(0.5f * (across[1].from + across[1].to), 1.75f, kStep);    // the forward lanes' divider

    RoadSegment oneWay = straightSegment(kMarkEdgeLines | kMarkAmerican | kMarkLeftHand);
    oneWay.centreOffset = -oneWay.halfWidth;
    oneWay.lanesBackward = 0;
    const Scene edges = roadScene({oneWay});
    const float line = 3.5f - kEdgeLineInset - 0.5f * kEdgeLineWidth;
    EXPECT_EQ(materialAt(edges, 5.0f, -line), kYellow);
    EXPECT_EQ(materialAt(edges, 5.0f, line), kWhite);
}
