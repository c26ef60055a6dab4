// roadElevations: decks at their clearance, ramps no steeper than kMaxRampSlope, one height per
// shared point, chains of bridge ways without dips.
#include "streets/road_elevation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

using namespace urbis;

namespace {

/// A straight way along y = `y` from x0 to x1, a point every `step` metres.
Road straight(double x0, double x1, double y, double step, bool bridge, int layer = 1) {
    Road r;
    const int n = int(std::lround(std::fabs(x1 - x0) / step));
    for (int i = 0; i <= n; ++i) r.centerline.push_back({x0 + (x1 - x0) * i / n, y});
    r.bridge = bridge;
    r.layer = bridge ? layer : 0;
    return r;
}

/// The steepest rise over run between consecutive points of any way.
double steepest(const std::vector<Road>& roads, const std::vector<std::vector<float>>& e) {
    double slope = 0;
    for (size_t w = 0; w < roads.size(); ++w)
        for (size_t i = 1; i < roads[w].centerline.size(); ++i) {
            const Vec2d a = roads[w].centerline[i - 1], b = roads[w].centerline[i];
            if (a.x == b.x && a.y == b.y) continue;
            slope = std::max(slope, std::fabs(double(e[w][i]) - e[w][i - 1]) / std::hypot(b.x - a.x, b.y - a.y));
        }
    return slope;
}

/// Fails unless every way through a point has the same height there.
void expectOneHeightPerPoint(const std::vector<Road>& roads, const std::vector<std::vector<float>>& e) {
    std::map<std::pair<double, double>, float> seen;
    for (size_t w = 0; w < roads.size(); ++w)
        for (size_t i = 0; i < roads[w].centerline.size(); ++i) {
            const auto [it, added] = seen.try_emplace({roads[w].centerline[i].x, roads[w].centerline[i].y}, e[w][i]);
            if (!added) {
                EXPECT_EQ(it->second, e[w][i]) << "way " << w << " point " << i;
            }
        }
}

} // namespace

TEST(StreetsBridgeElevation, ClearanceByLayer) {
    EXPECT_FLOAT_EQ(bridgeClearance(0), 5.0f);
    EXPECT_FLOAT_EQ(bridgeClearance(1), 6.0f);
    EXPECT_FLOAT_EQ(bridgeClearance(-1), 6.0f);
    EXPECT_FLOAT_EQ(bridgeClearance(2), 12.0f);
    EXPECT_FLOAT_EQ(bridgeClearance(3), 18.0f);
}

TEST(StreetsBridgeElevation, BridgeLandingOnJunctionsRampsOnItself) {
    // Ground way, bridge of 400 m, ground way; each landing is a junction (a side road meets there).
    std::vector<Road> roads = {straight(-200, 0, 0, 10, false), straight(0, 400, 0, 10, true),
                               straight(400, 600, 0, 10, false), Road{}, Road{}};
    roads[3].centerline = {{0, 0}, {0, -100}};
    roads[4].centerline = {{400, 0}, {400, 100}};
    const auto e = roadElevations(roads);
    EXPECT_EQ(e[1].front(), 0.0f);
    EXPECT_EQ(e[1].back(), 0.0f);
    EXPECT_FLOAT_EQ(e[1][20], 6.0f) << "the middle of a long bridge is at its clearance";
    // 6 m at 6 %: 100 m of ramp from each landing.
    EXPECT_NEAR(e[1][5], 0.06 * 50, 1e-4);
    EXPECT_FLOAT_EQ(e[1][10], 6.0f);
    for (float h : e[0]) EXPECT_EQ(h, 0.0f) << "a ground way beyond a junction stays on the ground";
    EXPECT_LE(steepest(roads, e), kMaxRampSlope + 1e-6);
    expectOneHeightPerPoint(roads, e);
}

TEST(StreetsBridgeElevation, ApproachesRampDownToTheGround) {
    // A bridge of 60 m between two approaches that end at junctions 200 m away: the deck keeps its
    // clearance and the approaches ramp down to the ground.
    std::vector<Road> roads = {straight(-200, 0, 0, 10, false), straight(0, 60, 0, 10, true),
                               straight(60, 260, 0, 10, false)};
    const auto e = roadElevations(roads);
    for (float h : e[1]) EXPECT_FLOAT_EQ(h, 6.0f);
    EXPECT_EQ(e[0].front(), 0.0f);
    EXPECT_EQ(e[2].back(), 0.0f);
    EXPECT_NEAR(e[0][15], 6.0 - 0.06 * 50, 1e-4);  // 50 m before the deck
    EXPECT_EQ(e[0][5], 0.0f);                       // 150 m before: on the ground
    EXPECT_LE(steepest(roads, e), kMaxRampSlope + 1e-6);
    expectOneHeightPerPoint(roads, e);
}

TEST(StreetsBridgeElevation, ShortBridgeBetweenNearDeadEndsStaysLow) {
    // Dead ends 20 m from both ends of a 20 m bridge: the slope allows 0.06 * 30 m at its middle.
    std::vector<Road> roads = {straight(-20, 0, 0, 5, false), straight(0, 20, 0, 5, true), straight(20, 40, 0, 5, false)};
    const auto e = roadElevations(roads);
    EXPECT_NEAR(e[1][2], 0.06 * 30, 1e-4);
    EXPECT_EQ(e[0].front(), 0.0f);
    EXPECT_LE(steepest(roads, e), kMaxRampSlope + 1e-6);
}

TEST(StreetsBridgeElevation, ChainOfBridgeWaysKeepsItsHeight) {
    // A viaduct mapped as ten ways of 40 m: no dip where they meet.
    std::vector<Road> roads;
    for (int k = 0; k < 10; ++k) roads.push_back(straight(40.0 * k, 40.0 * (k + 1), 0, 10, true, 2));
    roads.push_back(straight(-300, 0, 0, 10, false));
    roads.push_back(straight(400, 700, 0, 10, false));
    const auto e = roadElevations(roads);
    for (int k = 0; k < 10; ++k)
        for (float h : e[size_t(k)]) EXPECT_FLOAT_EQ(h, 12.0f) << "way " << k;
    EXPECT_LE(steepest(roads, e), kMaxRampSlope + 1e-6);
    expectOneHeightPerPoint(roads, e);
}

TEST(StreetsBridgeElevation, LayersMeetWithoutSteps) {
    // A layer 2 bridge continued by a layer 1 bridge: the higher one comes down to the lower one at
    // the ramp's slope, on its own length (the lower one's first point past the joint holds 6 m).
    std::vector<Road> roads = {straight(0, 300, 0, 10, true, 2), straight(300, 600, 0, 10, true, 1)};
    const auto e = roadElevations(roads);
    EXPECT_FLOAT_EQ(e[0].front(), 12.0f);
    EXPECT_FLOAT_EQ(e[1].back(), 6.0f);
    EXPECT_FLOAT_EQ(e[1][1], 6.0f);
    EXPECT_NEAR(e[0].back(), 6.0 + 0.06 * 10, 1e-4);
    EXPECT_NEAR(e[0][25], 6.0 + 0.06 * 60, 1e-4);
    EXPECT_FLOAT_EQ(e[0][20], 12.0f);
    EXPECT_LE(steepest(roads, e), kMaxRampSlope + 1e-6);
    expectOneHeightPerPoint(roads, e);
}

TEST(StreetsBridgeElevation, GridWithBridgesHasOneHeightPerPointAndGentleSlopes) {
    // A 6 x 6 grid of streets, every third block edge a bridge at layers 0..2, plus one way repeating
    // a point and one with a point at infinity: nothing crashes, one height per point, slopes bounded.
    std::vector<Road> roads;
    for (int row = 0; row <= 6; ++row)
        for (int col = 0; col < 6; ++col) {
            Road h = straight(80.0 * col, 80.0 * (col + 1), 80.0 * row, 20, (row + col) % 3 == 0, row % 3);
            Road v = h;
            for (Vec2d& p : v.centerline) p = {p.y, p.x};
            v.bridge = (row + col) % 4 == 1;
            v.layer = col % 3;
            roads.push_back(h);
            roads.push_back(v);
        }
    roads.push_back(Road{});
    roads.back().centerline = {{0, 0}, {0, 0}, {10, 0}};
    roads.push_back(Road{});
    roads.back().centerline = {{1e300, 1e300}, {INFINITY, 0}};
    roads.back().bridge = true;
    const auto e = roadElevations(roads);
    ASSERT_EQ(e.size(), roads.size());
    for (size_t w = 0; w < roads.size(); ++w) {
        ASSERT_EQ(e[w].size(), roads[w].centerline.size());
        for (float h : e[w]) EXPECT_TRUE(std::isfinite(h) && h >= 0.0f && h <= 18.0f);
    }
    roads.pop_back();
    EXPECT_LE(steepest(roads, e), kMaxRampSlope + 1e-6);
    expectOneHeightPerPoint(roads, e);
}
