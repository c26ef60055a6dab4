// Road markings in the export (export/road_marking_mesh.h) against the paint urbis lays per ray
// (geometry/road_markings.h): on West Oakland's roads every piece lies on its segment's carriageway
// at the road's height plus kMarkingLift and paints what roadPaintAt paints there, and every painted
// point of a road is covered; on a bending road the pieces follow its triangles.
#include "citygen/city_mesher.h"
#include "export/city_export.h"
#include "export/road_marking_mesh.h"
#include "geometry/road_markings.h"
#include "osm/osm_import.h"
#include "scene/surface_part.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <vector>

using namespace urbis;

namespace {

const std::string kOakland = URBIS_OSMNX_DATA "/West-Oakland.osm.bz2";

/// Height tolerance (m): the pieces are clipped in the segment's float coordinates and back.
constexpr float kHeightTolerance = 2e-3f;

struct MarkedCity {
    CityMesh mesh;
    TriangleMesh markings;
    std::vector<std::vector<size_t>> roadTriangles;   ///< of each segment
    std::map<uint32_t, std::vector<uint32_t>> segmentsOfRoad;
};

MarkedCity marked(CityMesh mesh) {
    MarkedCity m;
    m.mesh = std::move(mesh);
    m.markings = roadMarkingMesh(m.mesh.roadSegments, m.mesh.mesh);
    m.roadTriangles.resize(m.mesh.roadSegments.size());
    for (size_t k = 0; k < m.mesh.mesh.size(); ++k)
        if (m.mesh.mesh.info[k].part == uint32_t(SurfacePart::Road)) m.roadTriangles[m.mesh.mesh.info[k].object].push_back(k);
    for (uint32_t i = 0; i < m.mesh.roadSegments.size(); ++i) m.segmentsOfRoad[m.mesh.roadSegments[i].object].push_back(i);
    return m;
}

const MarkedCity& oakland() {
    static const MarkedCity m = marked(meshCity(importOsm(kOakland, ImportOptions{})));
    return m;
}

/// Barycentric coordinates of (x, z) in triangle t's plan; false if outside by more than `slack`.
bool inPlan(const Triangle& t, float x, float z, float slack, float& b1, float& b2) {
    const float ax = t.p1.x - t.p0.x, az = t.p1.z - t.p0.z, bx = t.p2.x - t.p0.x, bz = t.p2.z - t.p0.z;
    const float det = ax * bz - az * bx;
    if (std::fabs(det) < 1e-12f) return false;
    const float px = x - t.p0.x, pz = z - t.p0.z;
    b1 = (px * bz - pz * bx) / det;
    b2 = (ax * pz - az * px) / det;
    return b1 >= -slack && b2 >= -slack && b1 + b2 <= 1.0f + slack;
}

/// The height of the first of `triangles` of `mesh` over (x, z) in plan; NaN if none is.
float surfaceHeight(const TriangleMesh& mesh, const std::vector<size_t>& triangles, float x, float z, float slack) {
    for (size_t k : triangles) {
        const Triangle& t = mesh.triangles[k];
        float b1, b2;
        if (inPlan(t, x, z, slack, b1, b2)) return t.p0.y + b1 * (t.p1.y - t.p0.y) + b2 * (t.p2.y - t.p0.y);
    }
    return NAN;
}

/// Whether the point lies on segment s's carriageway in plan (within `slack` metres).
bool onCarriageway(const RoadSegment& s, Vec3f p, float slack) {
    const Vec2f road = roadCoordinates(s, p.x, p.z);
    return road.x >= -slack && road.x <= s.length + slack && std::fabs(road.y) <= s.halfWidth + slack;
}

/// Checks every marking piece of `m`: each vertex on a segment of its road, at that segment's road
/// surface plus kMarkingLift; the piece's centre painted by roadPaintAt, in its colour (`matching`
/// counts those; where bands overlap the export has both). Returns the pieces checked.
size_t expectPiecesOnTheirRoads(const MarkedCity& m, size_t& matching) {
    matching = 0;
    const TriangleMesh& marks = m.markings;
    for (size_t k = 0; k < marks.size(); ++k) {
        const Triangle& t = marks.triangles[k];
        const Vec3f centre = (t.p0 + t.p1 + t.p2) * (1.0f / 3.0f);
        const RoadSegment* on = nullptr;
        uint32_t index = 0;
        for (uint32_t i : m.segmentsOfRoad.at(marks.info[k].object)) {
            const RoadSegment& s = m.mesh.roadSegments[i];
            if (onCarriageway(s, centre, 1e-3f) && !std::isnan(surfaceHeight(m.mesh.mesh, m.roadTriangles[i], centre.x, centre.z, 1e-4f))) {
                on = &s;
                index = i;
                break;
            }
        }
        if (on == nullptr) {
            ADD_FAILURE() << "piece " << k << " at (" << centre.x << ", " << centre.z << ") lies on no segment of its road";
            continue;
        }
        for (const Vec3f& v : {t.p0, t.p1, t.p2}) {
            EXPECT_TRUE(onCarriageway(*on, v, 1e-3f)) << "piece " << k;
            const float y = surfaceHeight(m.mesh.mesh, m.roadTriangles[index], v.x, v.z, 1e-3f);
            EXPECT_NEAR(v.y, y + kMarkingLift, kHeightTolerance) << "piece " << k;
        }
        EXPECT_GT(cross(t.p1 - t.p0, t.p2 - t.p0).y, 0.0f) << "piece " << k << " faces down";
        const Vec2f road = roadCoordinates(*on, centre.x, centre.z);
        const RoadPaint paint = roadPaintAt(*on, road.x, road.y);
        EXPECT_NE(paint, kNoPaint) << "piece " << k << " where urbis paints nothing";
        matching += paint != kNoPaint && marks.info[k].material == on->paint + uint32_t(paint) - 1;
    }
    return marks.size();
}

} // namespace

TEST(ExportMarkings, OaklandPiecesLieOnTheirRoadsAtTheRoadsHeightInTheirPaint) {
    if (!std::filesystem::exists(kOakland)) GTEST_SKIP() << kOakland << " not found (Debian's python-osmnx-doc)";
    const MarkedCity& m = oakland();
    size_t matching = 0;
    const size_t pieces = expectPiecesOnTheirRoads(m, matching);
    std::set<uint32_t> roads, materials;
    for (size_t k = 0; k < m.markings.size(); ++k) roads.insert(m.markings.info[k].object), materials.insert(m.markings.info[k].material);
    std::printf("[ COUNTS   ] West Oakland: %zu marking triangles on %zu roads (%zu segments), %zu of them in roadPaintAt's colour\n",
                pieces, roads.size(), m.mesh.roadSegments.size(), matching);
    EXPECT_GT(pieces, 300u);
    EXPECT_EQ(materials.size(), 2u) << "white and yellow (the Americas' centre lines)";
    EXPECT_GE(double(matching), 0.99 * double(pieces)) << "only where two bands overlap may the colours differ";
}

TEST(ExportMarkings, OaklandEveryPaintedPointOfARoadIsCovered) {
    if (!std::filesystem::exists(kOakland)) GTEST_SKIP() << kOakland << " not found (Debian's python-osmnx-doc)";
    const MarkedCity& m = oakland();
    std::map<uint32_t, std::vector<size_t>> marksOfRoad;
    for (size_t k = 0; k < m.markings.size(); ++k) marksOfRoad[m.markings.info[k].object].push_back(k);
    size_t painted = 0, samples = 0, segments = 0;
    for (uint32_t i = 0; i < m.mesh.roadSegments.size(); ++i) {
        const RoadSegment& s = m.mesh.roadSegments[i];
        if (s.markings == 0 || m.roadTriangles[i].empty()) continue;
        ++segments;
        const std::vector<size_t>& marks = marksOfRoad[s.object];
        for (float along = 0.13f; along < s.length; along += 0.41f)
            for (float across = -s.halfWidth + 0.011f; across < s.halfWidth; across += 0.029f) {
                const RoadPaint paint = roadPaintAt(s, along, across);
                // Away from every line's edge (where a float's rounding decides), on this segment's triangles.
                bool edge = false;
                for (float e : {-3e-3f, 3e-3f})
                    edge |= roadPaintAt(s, along + e, across) != paint || roadPaintAt(s, along, across + e) != paint;
                const float x = s.start.x + along * s.direction.x + across * s.direction.y;
                const float z = s.start.y + along * s.direction.y - across * s.direction.x;
                const float road = surfaceHeight(m.mesh.mesh, m.roadTriangles[i], x, z, -1e-3f);
                if (edge || std::isnan(road)) continue;
                ++samples;
                std::set<uint32_t> found;   // the colours of the pieces over the point (bands may overlap)
                for (size_t k : marks) {
                    float b1, b2;
                    const Triangle& t = m.markings.triangles[k];
                    if (inPlan(t, x, z, 0.0f, b1, b2) && std::fabs(t.p0.y - road - kMarkingLift) < 0.5f)
                        found.insert(m.markings.info[k].material);
                }
                if (paint == kNoPaint) {
                    EXPECT_TRUE(found.empty()) << "segment " << i << " along " << along << " across " << across;
                } else {
                    ++painted;
                    EXPECT_EQ(found.count(s.paint + uint32_t(paint) - 1), 1u)
                        << "segment " << i << " along " << along << " across " << across;
                }
            }
    }
    std::printf("[ COUNTS   ] West Oakland: %zu marked segments, %zu points off the lines' edges, %zu of them painted\n",
                segments, samples, painted);
    EXPECT_GT(segments, 30u);
    EXPECT_GT(painted, 500u);
    EXPECT_GT(samples, 20 * painted);
}

TEST(ExportMarkings, PiecesFollowABendingRoadsTriangles) {
    // A 40 m two-lane road along +x, its carriageway cut into 4 m strips rising and falling (as on a
    // terrain): each strip two triangles at its own slope.
    RoadSegment s;
    s.start = {0.0f, 0.0f};
    s.direction = {1.0f, 0.0f};
    s.length = 40.0f;
    s.halfWidth = 3.5f;
    s.markings = kMarkCentreLine | kMarkCentreDashed | kMarkEdgeLines | kMarkStopAtEnd | kMarkZebraAtStart;
    s.object = 7;
    s.paint = 1;
    CityMesh mesh;
    const auto height = [](float x) { return 0.3f * std::sin(x * 0.35f) + 0.02f * x; };
    const TriangleInfo info{0, 0, uint32_t(SurfacePart::Road)};
    for (float x = 0.0f; x < 40.0f; x += 4.0f) {
        const Vec3f a{x, height(x), 3.5f}, b{x + 4.0f, height(x + 4.0f), 3.5f};
        const Vec3f c{x + 4.0f, height(x + 4.0f), -3.5f}, d{x, height(x), -3.5f};
        mesh.mesh.add({a, b, c}, info);
        mesh.mesh.add({a, c, d}, info);
    }
    mesh.roadSegments = {s};
    const MarkedCity m = marked(mesh);
    size_t matching = 0;
    ASSERT_GT(expectPiecesOnTheirRoads(m, matching), 0u);
    EXPECT_EQ(matching, m.markings.size());
    // The pieces cover the bands' rectangles, each band whole (overlaps twice), summed in plan: the
    // zebra's 7 stripes over the first 1.5 m, the rest from there: both edge lines, the centre line's
    // dashes (at 0, 9, 18, 27 and 36 m of the 3 m / 6 m rhythm: 1.5 m of the first), the stop line
    // over the forward half.
    double area = 0;
    for (const Triangle& t : m.markings.triangles) area += 0.5 * double(cross(t.p1 - t.p0, t.p2 - t.p0).y);
    using namespace marking;
    const double zebra = 7.0 * kZebraStripeWidth * 0.5 * kZebraBand, lines = 40.0 - 0.5 * kZebraBand;
    const double expected = zebra + 2.0 * lines * kEdgeLineWidth + (1.5 + 4.0 * kDashLength) * kLineWidth +
                            3.5 * kStopLineWidth;
    EXPECT_NEAR(area, expected, 1e-3 * expected);
}
