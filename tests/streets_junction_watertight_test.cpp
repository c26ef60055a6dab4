// Junctions are watertight: vertical rays on a grid over every junction polygon, and a margin into the
// roads that meet there, hit a carriageway or the junction, never the ground; and no point lies on two
// coplanar street triangles at once (no overlaps). Hand-made 3-, 4- and 5-way junctions with acute
// angles and unequal widths, a two-road mitre, and every junction of the osmnx village extract.
#include "streets_network_support.h"

#include "layout/city_layout.h"
#include "osm/osm_import.h"
#include "streets/street_levels.h"

#include <gtest/gtest.h>

#include <iostream>
#include <string>

using namespace urbis;
using namespace urbis::test;

namespace {

struct Probe {
    size_t rays = 0, ground = 0, wrongPart = 0, doubled = 0;
};

void probe(const Network& net, const FlatTriangles& flat, Vec2d p, Probe& out) {
    ++out.rays;
    const SurfaceHit h = net.down(p);
    if (isGround(h)) {
        ++out.ground;
        return;
    }
    if (h.part != SurfacePart::Road && h.part != SurfacePart::Junction) ++out.wrongPart;
    if (flat.covering(p, h.position.y) > 1) ++out.doubled;
}

/// Rays over junction j (0.2 m grid, 5 mm inside its border) and 1 m into each road's trimmed end.
Probe probeJunction(const Network& net, const FlatTriangles& flat, const JunctionShape& j) {
    Probe out;
    Vec2d lo{1e30, 1e30}, hi{-1e30, -1e30};
    for (const Vec2d& p : j.ring) {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    }
    for (double x = lo.x; x <= hi.x; x += 0.2)
        for (double y = lo.y; y <= hi.y; y += 0.2)
            if (inside(j.ring, {x, y}) && distanceToRing(j.ring, {x, y}) > 5e-3) probe(net, flat, {x, y}, out);
    const PointKey centre(j.centre);
    for (size_t r = 0; r < net.fitted.size(); ++r) {
        const Road& road = net.fitted[r];
        if (isPath(road.highway) || net.shapes.consumed[r]) continue;
        for (const bool atEnd : {false, true}) {
            if (!(PointKey(atEnd ? road.centerline.back() : road.centerline.front()) == centre)) continue;
            const RoadEnd& e = atEnd ? net.shapes.ends[r] : net.shapes.starts[r];
            const Vec2d across{e.left.x - e.right.x, e.left.y - e.right.y};
            const double w = std::hypot(across.x, across.y);
            // Into the road: against its direction at its last point, along it at its first.
            const Vec2d into = atEnd ? Vec2d{-across.y / w, across.x / w} : Vec2d{across.y / w, -across.x / w};
            // Straight in across the trimmed end's middle: the road may bend away beyond.
            for (double f = 0.15; f < 0.9; f += 0.1)
                for (double g : {0.02, 0.5, 1.0})
                    probe(net, flat,
                          {e.right.x + across.x * f + into.x * g, e.right.y + across.y * f + into.y * g}, out);
        }
    }
    return out;
}

void expectWatertight(const Network& net, const std::string& name) {
    const FlatTriangles flat(net.mesh.mesh);
    ASSERT_FALSE(net.shapes.junctions.empty()) << name;
    for (size_t k = 0; k < net.shapes.junctions.size(); ++k) {
        const JunctionShape& j = net.shapes.junctions[k];
        if (j.path) continue;
        const Probe p = probeJunction(net, flat, j);
        EXPECT_GT(p.rays, 20u) << name << " junction " << k;
        EXPECT_EQ(p.ground, 0u) << name << " junction " << k << " at " << j.centre.x << ", " << j.centre.y;
        EXPECT_EQ(p.wrongPart, 0u) << name << " junction " << k << " at " << j.centre.x << ", " << j.centre.y;
        EXPECT_EQ(p.doubled, 0u) << name << " junction " << k << " at " << j.centre.x << ", " << j.centre.y;
    }
}

struct StarCase {
    const char* name;
    std::vector<double> degrees;
    std::vector<float> widths;
};

void PrintTo(const StarCase& c, std::ostream* os) { *os << c.name; }

class HandMadeJunction : public testing::TestWithParam<StarCase> {};

} // namespace

TEST_P(HandMadeJunction, IsWatertight) {
    const StarCase& c = GetParam();
    const Network net(star(c.degrees, c.widths));
    ASSERT_EQ(net.shapes.junctions.size(), 1u);
    expectWatertight(net, c.name);
    // A sidewalk corner joins every pair of neighbours (all have sidewalks on both sides).
    EXPECT_EQ(net.shapes.corners.size(), c.degrees.size());
}

INSTANTIATE_TEST_SUITE_P(Streets, HandMadeJunction,
                         testing::Values(StarCase{"ThreeWayAcute", {0, 25, 180}, {6, 6, 8}},
                                         StarCase{"FourWay", {0, 80, 170, 260}, {6, 9, 6, 4}},
                                         StarCase{"FiveWayAcute", {0, 30, 100, 200, 290}, {6, 6, 7, 5, 9}},
                                         StarCase{"WideGap", {0, 40, 80}, {6, 6, 6}}));

TEST(StreetsJunction, TwoRoadMitreHasNoGap) {
    // A right-angled bend where two ways meet: east from the node and north from it.
    CityModel city;
    city.roads.push_back(test::street({{30, 0}, {0, 0}}));
    city.roads.push_back(test::street({{0, 0}, {0, 30}}));
    const Network net(city);
    ASSERT_EQ(net.fitted.size(), 2u);
    EXPECT_TRUE(net.shapes.junctions.empty());
    const FlatTriangles flat(net.mesh.mesh);
    size_t ground = 0, doubled = 0, rays = 0;
    // The carriageways' union near the bend: x in [-3, 3] going north, y in [-3, 3] going east, and
    // the outer corner [-3, 0] x [-3, 0].
    for (double x = -2.95; x <= 6.0; x += 0.1)
        for (double y = -2.95; y <= 6.0; y += 0.1) {
            if (std::fabs(x) > 2.95 && std::fabs(y) > 2.95) continue;
            ++rays;
            const SurfaceHit h = net.down({x, y});
            ground += isGround(h) ? 1 : 0;
            if (!isGround(h)) {
                EXPECT_EQ(h.part, SurfacePart::Road) << x << ", " << y;
                doubled += flat.covering({x, y}, h.position.y) > 1 ? 1 : 0;
            }
        }
    EXPECT_GT(rays, 1000u);
    EXPECT_EQ(ground, 0u);
    EXPECT_EQ(doubled, 0u);
}

TEST(StreetsJunction, VillageJunctionsAreWatertight) {
    const std::string path = std::string(URBIS_OSMNX_DATA) + "/planet_10.068,48.135_10.071,48.137.osm";
    const CityModel city = importOsm(path, {});
    const Network net(city);
    expectWatertight(net, "village");
    size_t carriageway = 0;
    for (const JunctionShape& j : net.shapes.junctions) carriageway += j.path ? 0 : 1;
    EXPECT_GE(carriageway, 3u);
}

TEST(StreetsJunction, GeneratedCityJunctionsAreWatertight) {
    LayoutParams params;
    params.buildings = 3000;   // big enough for the river, its bridges and arterial junctions
    const Network net(generateCity(params));
    const FlatTriangles flat(net.mesh.mesh);
    size_t junctions = 0, leaky = 0, ground = 0;
    for (const JunctionShape& j : net.shapes.junctions) {
        if (j.path) continue;
        const Probe p = probeJunction(net, flat, j);
        ++junctions;
        ground += p.ground;
        leaky += p.ground + p.wrongPart + p.doubled > 0 ? 1 : 0;
    }
    std::cout << leaky << " of " << junctions << " junctions with a ray on a sidewalk or two surfaces\n";
    EXPECT_GE(junctions, 100u);
    EXPECT_EQ(ground, 0u) << "no ray over a junction reaches the ground";
    // 10 of 266 (3.8 %) are not, all of them junctions merged where an arterial (a diagonal or the
    // ring) crosses the grid 20-25 m from a grid junction: the three junctions' trims overlap, so they
    // merge into one (before the merge took roads of any length, 27 of 286 had the neighbours' surfaces
    // over them). In the merged ones 1-2 % of the rays find a sidewalk or a second plane: where two
    // neighbouring ends' edges do not cross ahead of both, the border runs straight between their
    // corners, across the corner of the other's corridor. Held at 4 %; no ray reaches the ground.
    EXPECT_LE(double(leaky), 0.04 * double(junctions));
}
