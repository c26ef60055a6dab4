// On the real San Francisco extract: wherever a bridge crosses a road on the ground in plan, a ray down
// from high above meets the deck first, high over the road, and a ray up from the road meets the
// deck's underside at least 4 m above the road's top. (Roads lifted where they pass under, approaches
// of other decks such as Embarcadero Center's walkways, are counted apart: a flat city cannot stack
// them all.)
#include "geometry/scene_intersect.h"
#include "osm/osm_import.h"
#include "scene/scene.h"
#include "streets/bridge_deck.h"
#include "streets/road_elevation.h"
#include "streets/road_fitting.h"
#include "streets/street_levels.h"
#include "streets/street_materials.h"
#include "streets/street_mesher.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

using namespace urbis;

namespace {

const std::string kShared = URBIS_SHARED_DATA;

/// Where a bridge segment crosses a ground segment in plan, and the heights of both there.
struct PlanCrossing {
    Vec2d point;
    float deck = 0, ground = 0;  ///< elevations of the bridge and of the ground road at the point
    int64_t bridge = 0, road = 0;
};

struct Box {
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    explicit Box(const std::vector<Vec2d>& line) {
        for (const Vec2d& p : line) {
            x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
        }
    }
    bool overlaps(const Box& o) const { return x0 <= o.x1 && o.x0 <= x1 && y0 <= o.y1 && o.y0 <= y1; }
};

/// Proper crossings (inside both segments, not at a shared point) of every bridge and ground road.
std::vector<PlanCrossing> planCrossings(const std::vector<Road>& roads, const std::vector<std::vector<float>>& e) {
    std::vector<Box> boxes;
    for (const Road& r : roads) boxes.emplace_back(r.centerline);
    std::vector<PlanCrossing> out;
    for (size_t b = 0; b < roads.size(); ++b) {
        if (!roads[b].bridge || !atSurface(roads[b])) continue;
        for (size_t g = 0; g < roads.size(); ++g) {
            if (roads[g].bridge || !atSurface(roads[g]) || !boxes[b].overlaps(boxes[g])) continue;
            const std::vector<Vec2d>&p = roads[b].centerline, &q = roads[g].centerline;
            for (size_t i = 1; i < p.size(); ++i)
                for (size_t j = 1; j < q.size(); ++j) {
                    const double rx = p[i].x - p[i - 1].x, ry = p[i].y - p[i - 1].y;
                    const double sx = q[j].x - q[j - 1].x, sy = q[j].y - q[j - 1].y, den = rx * sy - ry * sx;
                    if (std::fabs(den) < 1e-9) continue;
                    const double qx = q[j - 1].x - p[i - 1].x, qy = q[j - 1].y - p[i - 1].y;
                    const double t = (qx * sy - qy * sx) / den, u = (qx * ry - qy * rx) / den;
                    if (t <= 0.01 || t >= 0.99 || u <= 0.01 || u >= 0.99) continue;
                    out.push_back({{p[i - 1].x + t * rx, p[i - 1].y + t * ry},
                                   float(e[b][i - 1] + t * (e[b][i] - e[b][i - 1])),
                                   float(e[g][j - 1] + u * (e[g][j] - e[g][j - 1])), roads[b].osmId, roads[g].osmId});
                }
        }
    }
    return out;
}

bool isDeckPart(SurfacePart part) {
    return part == SurfacePart::BridgeDeck || part == SurfacePart::Parapet || part == SurfacePart::Road ||
           part == SurfacePart::Junction || part == SurfacePart::Sidewalk;
}

} // namespace

TEST(StreetsBridgeSf, DecksLieAboveTheRoadsTheyCross) {
    const std::string path = kShared + "/sf_downtown_2023.osm.pbf";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " not found, skipping";
    const CityModel city = importOsm(path, {});
    // The roads as meshStreets draws them: fitted (cut where they run through a building), then lifted.
    std::map<std::string, uint64_t> dropped;
    const std::vector<Road> fitted = fitRoads(city, dropped);
    const std::vector<std::vector<float>> e = roadElevations(fitted);
    const StreetMesh streets = meshStreets(city, StreetOptions{});
    const Scene scene = Scene::build({.mesh = streets.mesh, .materials = streetMaterials()});
    const std::vector<PlanCrossing> crossings = planCrossings(fitted, e);
    std::cout << crossings.size() << " crossings of a bridge over a ground road in plan\n";
    ASSERT_GT(crossings.size(), 20u) << "the extract's freeways cross many streets";
    size_t failures = 0, lifted = 0;
    for (const PlanCrossing& c : crossings) {
        if (c.ground > 0.5f) {
            ++lifted;
            continue;
        }
        const float roadTop = kRoadLevel + c.ground;
        const SurfaceHit above = traceScene(scene.view(), Ray{worldFromStreet(c.point, 500.0), Vec3f{0, -1, 0}}, false);
        // From just above whatever lies on the ground there: a carriageway, or a sidewalk mapped as its own way.
        const SurfaceHit below =
            traceScene(scene.view(), Ray{worldFromStreet(c.point, kSidewalkLevel + c.ground + 0.05), Vec3f{0, 1, 0}}, false);
        const bool ok = above.valid() && isDeckPart(above.part) && above.position.y > roadTop + 4.0f && below.valid() &&
                        below.part == SurfacePart::BridgeDeck && below.position.y >= roadTop + 4.0f;
        if (!ok && ++failures <= 20)
            ADD_FAILURE() << "bridge w" << c.bridge << " over w" << c.road << " at (" << c.point.x << ", " << c.point.y
                          << "): deck " << c.deck << " m, road " << c.ground << " m; from above "
                          << (above.valid() ? above.position.y : -1.0f) << " m, from below "
                          << (below.valid() ? below.position.y : -1.0f) << " m";
    }
    std::cout << lifted << " of them over a road lifted there (an approach of another deck)\n";
    EXPECT_LE(lifted, crossings.size() / 20);
    EXPECT_EQ(failures, 0u) << "of " << crossings.size() - lifted;
}
