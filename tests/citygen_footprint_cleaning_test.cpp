// Footprint cleaning: what CGAL's straight skeleton is fed, and what the walls are built on.
#include "citygen/footprint_cleaning.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace urbis;

namespace {

bool same(const Ring& a, const Ring& b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i)
        if (a[i].x != b[i].x || a[i].y != b[i].y) return false;
    return true;
}

const Ring kSquare = {{0, 0}, {20, 0}, {20, 20}, {0, 20}};

} // namespace

TEST(FootprintCleaning, DropsRepeatedCloseAndCollinearPoints) {
    // An entrance node 2 mm off the wall, a repeated point, one 5 mm from its predecessor.
    const Polygon dirty{{{0, 0}, {10, 0.002}, {20, 0}, {20, 0}, {20, 20}, {20.005, 20}, {0, 20}}, {}};
    const auto cleaned = cleanFootprint(dirty);
    ASSERT_TRUE(cleaned);
    EXPECT_TRUE(same(cleaned->polygon.outer, kSquare));
}

TEST(FootprintCleaning, KeepsRealCornersAndTheInputsOwnPoints) {
    const Polygon notch{{{0, 0}, {10, 0}, {10, 0.05}, {10.05, 0.05}, {10.05, 0}, {20, 0}, {20, 20}, {0, 20}}, {}};
    const auto cleaned = cleanFootprint(notch);
    ASSERT_TRUE(cleaned);
    EXPECT_TRUE(same(cleaned->polygon.outer, notch.outer));  // a 5 cm notch is a shape, not noise
}

TEST(FootprintCleaning, OrientsOuterCounterClockwiseAndHolesClockwise) {
    const Polygon inverted{{{0, 0}, {0, 20}, {20, 20}, {20, 0}}, {{{5, 5}, {15, 5}, {15, 15}, {5, 15}}}};
    const auto cleaned = cleanFootprint(inverted);
    ASSERT_TRUE(cleaned);
    const Ring& outer = cleaned->polygon.outer;
    ASSERT_EQ(cleaned->polygon.holes.size(), 1u);
    const Ring& hole = cleaned->polygon.holes[0];
    auto area2 = [](const Ring& r) {
        double a = 0;
        for (size_t i = 0; i < r.size(); ++i) a += r[i].x * r[(i + 1) % r.size()].y - r[(i + 1) % r.size()].x * r[i].y;
        return a;
    };
    EXPECT_GT(area2(outer), 0);
    EXPECT_LT(area2(hole), 0);
}

TEST(FootprintCleaning, DropsHolesTouchingTheOuterRingOrEachOther) {
    // What GEOSMakeValid leaves of a bow-tie: a sliver hole sharing a point with the outer ring.
    Polygon touching{kSquare, {{{0, 0}, {5, 8}, {8, 5}}, {{10, 10}, {10, 15}, {15, 15}, {15, 10}}, {{15, 15}, {15, 18}, {18, 18}}}};
    const auto cleaned = cleanFootprint(touching);
    ASSERT_TRUE(cleaned);
    EXPECT_EQ(cleaned->holesDropped, 2u);
    ASSERT_EQ(cleaned->polygon.holes.size(), 1u);
    EXPECT_EQ(cleaned->polygon.holes[0].size(), 4u);
}

TEST(FootprintCleaning, DropsTinyAndDegenerateHoles) {
    const Polygon tiny{kSquare, {{{5, 5}, {5.05, 5}, {5.05, 5.05}, {5, 5.05}}, {{8, 8}, {9, 9}}}};
    const auto cleaned = cleanFootprint(tiny);
    ASSERT_TRUE(cleaned);
    EXPECT_EQ(cleaned->holesDropped, 2u);
    EXPECT_TRUE(cleaned->polygon.holes.empty());
}

TEST(FootprintCleaning, RefusesWhatIsNoPolygon) {
    EXPECT_FALSE(cleanFootprint(Polygon{{{0, 0}, {1, 1}}, {}}));
    EXPECT_FALSE(cleanFootprint(Polygon{{{0, 0}, {10, 0}, {20, 0.001}}, {}}));  // collinear: no area
    EXPECT_FALSE(cleanFootprint(Polygon{{{0, 0}, {10, 0}, {10, NAN}}, {}}));
}
