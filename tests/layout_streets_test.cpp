// Generated city: its streets carry what the OSM import gives streets (class, lanes, widths,
// sidewalks, surface), share a vertex at every junction (arterials with the grid included), carry
// crossings on their vertices, keep a bigger city's centre unchanged, and its parks have paths.
#include "layout/city_layout.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

using namespace urbis;

namespace {

CityModel cityOf(uint64_t buildings, uint32_t seed) {
    LayoutParams p;
    p.buildings = buildings;
    p.seed = seed;
    return generateCity(p);
}

// A city large enough for diagonal and ring arterials, the river and every district.
const CityModel& bigCity() {
    static const CityModel city = cityOf(12'000, 3);
    return city;
}

bool same(Vec2d a, Vec2d b) { return a.x == b.x && a.y == b.y; }

bool carriesTraffic(HighwayClass c) {
    return c == HighwayClass::Primary || c == HighwayClass::Secondary || c == HighwayClass::Tertiary ||
           c == HighwayClass::Residential;
}

bool axisAligned(const Road& r) {
    return std::all_of(r.centerline.begin(), r.centerline.end(),
                       [&](Vec2d p) { return p.x == r.centerline[0].x; }) ||
           std::all_of(r.centerline.begin(), r.centerline.end(), [&](Vec2d p) { return p.y == r.centerline[0].y; });
}

using PointKey = std::pair<double, double>;
PointKey keyOf(Vec2d p) { return {p.x, p.y}; }

// How many distinct roads have a vertex at each point.
std::map<PointKey, std::set<size_t>> vertexOwners(const CityModel& city) {
    std::map<PointKey, std::set<size_t>> out;
    for (size_t r = 0; r < city.roads.size(); ++r)
        for (Vec2d p : city.roads[r].centerline) out[keyOf(p)].insert(r);
    return out;
}

double orient(Vec2d a, Vec2d b, Vec2d c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); }

bool onSegment(Vec2d a, Vec2d b, Vec2d p) {
    return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
           p.y <= std::max(a.y, b.y);
}

// Whether closed segments a-b and c-d have a point in common.
bool meet(Vec2d a, Vec2d b, Vec2d c, Vec2d d) {
    const double o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
    if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0))) return true;
    return (o1 == 0 && onSegment(a, b, c)) || (o2 == 0 && onSegment(a, b, d)) || (o3 == 0 && onSegment(c, d, a)) ||
           (o4 == 0 && onSegment(c, d, b));
}

struct Segment {
    size_t road;
    Vec2d a, b;
};

// Two roads of `city` never meet except at a vertex of both; the arterials meet the grid there.
void expectSharedVerticesAtCrossings(const CityModel& city) {
    constexpr double kCell = 60.0;
    std::vector<Segment> segments;
    std::map<std::pair<long, long>, std::vector<size_t>> cells;
    for (size_t r = 0; r < city.roads.size(); ++r) {
        const std::vector<Vec2d>& c = city.roads[r].centerline;
        for (size_t i = 0; i + 1 < c.size(); ++i) {
            const size_t s = segments.size();
            segments.push_back({r, c[i], c[i + 1]});
            for (long x = long(std::floor(std::min(c[i].x, c[i + 1].x) / kCell));
                 x <= long(std::floor(std::max(c[i].x, c[i + 1].x) / kCell)); ++x)
                for (long y = long(std::floor(std::min(c[i].y, c[i + 1].y) / kCell));
                     y <= long(std::floor(std::max(c[i].y, c[i + 1].y) / kCell)); ++y)
                    cells[{x, y}].push_back(s);
        }
    }
    std::set<std::pair<size_t, size_t>> bad;
    for (const auto& [cell, in] : cells)
        for (size_t i = 0; i < in.size(); ++i)
            for (size_t j = i + 1; j < in.size(); ++j) {
                const Segment &s = segments[in[i]], &t = segments[in[j]];
                if (s.road == t.road || !meet(s.a, s.b, t.a, t.b)) continue;
                const bool shared = same(s.a, t.a) || same(s.a, t.b) || same(s.b, t.a) || same(s.b, t.b);
                if (!shared) bad.insert({std::min(s.road, t.road), std::max(s.road, t.road)});
            }
    for (const auto& [r, q] : bad) ADD_FAILURE() << "roads " << r << " and " << q << " cross without a shared vertex";

    // The arterials do meet the grid, at vertices of both.
    size_t arterialJunctions = 0;
    const auto owners = vertexOwners(city);
    for (const Road& r : city.roads) {
        if (axisAligned(r) || r.highway != HighwayClass::Primary) continue;
        for (Vec2d p : r.centerline) {
            const std::set<size_t>& o = owners.at(keyOf(p));
            arterialJunctions += std::any_of(o.begin(), o.end(), [&](size_t q) { return axisAligned(city.roads[q]); });
        }
    }
    EXPECT_GT(arterialJunctions, 20u);
}

} // namespace

TEST(LayoutStreets, RoadsShareAVertexAtEveryCrossing) {
    expectSharedVerticesAtCrossings(bigCity());
    for (uint32_t seed : {1u, 2u, 4u}) {
        SCOPED_TRACE(seed);
        expectSharedVerticesAtCrossings(cityOf(12'000, seed));
    }
}

TEST(LayoutStreets, LanesSidewalksAndSurfacesByClass) {
    std::map<HighwayClass, size_t> classes;
    size_t oneWays = 0, singleLane = 0;
    for (const Road& r : bigCity().roads) {
        ++classes[r.highway];
        if (!carriesTraffic(r.highway)) {
            EXPECT_TRUE(r.highway == HighwayClass::Footway || r.highway == HighwayClass::Path);
            EXPECT_EQ(r.sidewalk, Sidewalk::None);
            EXPECT_FALSE(r.laneMarkings);
            continue;
        }
        EXPECT_EQ(r.lanesForward + r.lanesBackward, r.lanes);
        EXPECT_GE(r.width / float(r.lanes), 3.0f) << "lane width";
        EXPECT_LE(r.width / float(r.lanes), 3.5f) << "lane width";
        EXPECT_EQ(r.sidewalk, Sidewalk::Both);
        EXPECT_GE(r.sidewalkLeftWidth, 2.5f);
        EXPECT_LE(r.sidewalkLeftWidth, 4.0f);
        EXPECT_EQ(r.sidewalkLeftWidth, r.sidewalkRightWidth);
        EXPECT_EQ(r.surface, RoadSurface::Asphalt);
        EXPECT_TRUE(r.laneMarkings);
        if (r.oneway) {
            EXPECT_EQ(r.lanesBackward, 0);
            EXPECT_LE(r.lanes, 2);
            ++oneWays;
            singleLane += r.lanes == 1 ? 1 : 0;
        }
        switch (r.highway) {
        case HighwayClass::Primary:
            EXPECT_GE(r.lanes, 4);
            EXPECT_LE(r.lanes, 6);
            EXPECT_FALSE(r.overtaking);
            break;
        case HighwayClass::Secondary: EXPECT_EQ(r.lanes, 4); break;
        case HighwayClass::Tertiary: EXPECT_EQ(r.lanes, 2); break;
        default: EXPECT_LE(r.lanes, 2); break;
        }
    }
    for (HighwayClass c : {HighwayClass::Primary, HighwayClass::Secondary, HighwayClass::Tertiary,
                           HighwayClass::Residential, HighwayClass::Footway})
        EXPECT_GT(classes[c], 0u) << int(c);
    EXPECT_GT(oneWays, 0u);
    EXPECT_GT(singleLane, 0u);
}

TEST(LayoutStreets, CrossingsLieOnRoadVerticesNearJunctions) {
    const CityModel& city = bigCity();
    ASSERT_GT(city.crossings.size(), 50u);
    const auto owners = vertexOwners(city);
    std::map<CrossingKind, size_t> kinds;
    for (const Crossing& c : city.crossings) {
        ++kinds[c.kind];
        auto it = owners.find(keyOf(c.position));
        ASSERT_NE(it, owners.end()) << "crossing at " << c.position.x << ", " << c.position.y << " is not a road vertex";
        // One road carries it: it is no junction.
        const Road& road = city.roads[*it->second.begin()];
        for (size_t r : it->second) EXPECT_EQ(city.roads[r].highway, road.highway);
        EXPECT_LE(it->second.size(), 1u) << "a crossing is not at a junction";
        if (road.highway == HighwayClass::Residential || road.highway == HighwayClass::Tertiary)
            EXPECT_EQ(c.kind, CrossingKind::Zebra);
        else EXPECT_TRUE(c.kind == CrossingKind::Marked || c.kind == CrossingKind::TrafficSignals);
        // A few metres from a junction along its road.
        double nearest = 1e300;
        const std::vector<Vec2d>& line = road.centerline;
        const size_t at = size_t(std::find_if(line.begin(), line.end(), [&](Vec2d p) { return same(p, c.position); }) -
                                 line.begin());
        for (int step : {-1, 1}) {
            double along = 0;
            for (size_t i = at; (step < 0 ? i > 0 : i + 1 < line.size()); i += size_t(step)) {
                const Vec2d p = line[i], q = line[i + size_t(step)];
                along += std::hypot(q.x - p.x, q.y - p.y);
                if (owners.at(keyOf(q)).size() > 1) {
                    nearest = std::min(nearest, along);
                    break;
                }
            }
        }
        EXPECT_GT(nearest, 3.0);
        EXPECT_LT(nearest, 60.0);
    }
    EXPECT_GT(kinds[CrossingKind::Zebra], 0u);
    EXPECT_GT(kinds[CrossingKind::Marked], 0u);
    EXPECT_GT(kinds[CrossingKind::TrafficSignals], 0u);
}

TEST(LayoutStreets, ParksHavePathsAndTheCentreHasPlazas) {
    const CityModel& city = bigCity();
    size_t parks = 0, plazas = 0, paths = 0;
    std::vector<const Area*> parkAreas;
    for (const Area& a : city.areas) {
        if (a.kind == AreaKind::Park) parkAreas.push_back(&a);
        if (a.kind == AreaKind::Pedestrian) {
            ++plazas;
            EXPECT_TRUE(a.surface == RoadSurface::Sett || a.surface == RoadSurface::PavingStones);
        }
    }
    parks = parkAreas.size();
    for (const Road& r : city.roads) {
        if (r.highway != HighwayClass::Footway && r.highway != HighwayClass::Path) continue;
        ++paths;
        // Inside (or on the edge of) one park's rectangle.
        const bool inside = std::any_of(parkAreas.begin(), parkAreas.end(), [&](const Area* a) {
            const Ring& o = a->polygon.outer;
            return std::all_of(r.centerline.begin(), r.centerline.end(), [&](Vec2d p) {
                return p.x >= o[0].x && p.x <= o[2].x && p.y >= o[0].y && p.y <= o[2].y;
            });
        });
        EXPECT_TRUE(inside);
    }
    EXPECT_GT(parks, 0u);
    EXPECT_GE(paths, 2 * parks);
    EXPECT_GT(plazas, 0u);
}

TEST(LayoutStreets, SameSeedSameStreetsAndABiggerCityKeepsTheCentre) {
    const CityModel small = cityOf(3000, 3);
    const CityModel& big = bigCity();
    constexpr double kCentre = 400.0;  // m: well inside the smaller city
    auto inCentre = [&](Vec2d p) { return std::hypot(p.x, p.y) < kCentre; };
    using Piece = std::tuple<PointKey, PointKey, int, float, bool>;
    auto pieces = [&](const CityModel& c) {
        std::set<Piece> out;
        for (const Road& r : c.roads)
            for (size_t i = 0; i + 1 < r.centerline.size(); ++i)
                if (inCentre(r.centerline[i]) && inCentre(r.centerline[i + 1]))
                    out.insert({keyOf(r.centerline[i]), keyOf(r.centerline[i + 1]), int(r.highway), r.width, r.bridge});
        return out;
    };
    const std::set<Piece> a = pieces(small), b = pieces(big);
    ASSERT_GT(a.size(), 100u);
    for (const Piece& p : a)
        EXPECT_TRUE(b.count(p)) << "the smaller city's segment (" << std::get<0>(p).first << ", " << std::get<0>(p).second
                                << ") - (" << std::get<1>(p).first << ", " << std::get<1>(p).second << "), class "
                                << std::get<2>(p) << ", is not in the bigger";
    std::set<std::pair<PointKey, int>> crossingsA, crossingsB;
    for (const Crossing& c : small.crossings)
        if (inCentre(c.position)) crossingsA.insert({keyOf(c.position), int(c.kind)});
    for (const Crossing& c : big.crossings)
        if (inCentre(c.position)) crossingsB.insert({keyOf(c.position), int(c.kind)});
    EXPECT_GT(crossingsA.size(), 10u);
    EXPECT_EQ(crossingsA, crossingsB);
}
