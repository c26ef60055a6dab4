// Roof shapes against analytic volumes: each building (floor, walls, roof, gables) is a closed
// mesh whose volume, by the divergence theorem, is the footprint prism below the wall top plus the
// roof's own volume. Buildings stand 2 m above the ground so that they have a floor.
#include "mesh_checks.h"
#include "roof_test_buildings.h"

#include <gtest/gtest.h>

using namespace urbis;
using namespace urbis::test;

namespace {

constexpr float kMin = 2.0f, kHeight = 12.0f, kRoof = 4.0f;  // walls from 2 m to 8 m, roof 4 m

/// Volume of the roof alone: the closed building less its prism of walls.
double roofVolume(const Building& b) {
    const CityMesh out = meshOne(b);
    EXPECT_EQ(openEdges(out.mesh), 0u);
    EXPECT_TRUE(out.roofFallbacks.empty());
    return closedVolume(out.mesh) - ringArea(b.footprint.outer) * (b.height - b.roofHeight - b.minHeight);
}

/// Integral over [t0, t1] of the area of a w x d rectangle inset by t (exact: Simpson on a quadratic).
double insetAreaIntegral(double w, double d, double t0, double t1) {
    auto area = [&](double t) { return (w - 2 * t) * (d - 2 * t); };
    return (t1 - t0) / 6 * (area(t0) + 4 * area(0.5 * (t0 + t1)) + area(t1));
}

} // namespace

TEST(RoofVolume, GabledPrismIsHalfTheBox) {
    EXPECT_NEAR(roofVolume(roofed(rectangle(20, 10), RoofShape::Gabled, kMin, kHeight, kRoof)), 20 * 10 * kRoof / 2, 1e-3);
}

TEST(RoofVolume, GabledLShapeHasARidgeAndAGablePerWing) {
    // lShape: two wings w = 8 m wide and 20 m long. Each wing is a gabled prism (cross-section w H / 2)
    // up to its gable; where the wings meet, the hip outside and the valley inside enclose as much as
    // a w x w piece of prism, so V = (w H / 2)(20 + 20 - w). Hipped wing ends would leave out two
    // pyramids; one ridge across the whole footprint would give another volume.
    const double w = 8;
    EXPECT_NEAR(roofVolume(roofed(lShape(), RoofShape::Gabled, kMin, kHeight, kRoof)), w * kRoof / 2 * (20 + 20 - w), 1e-3);
}

TEST(RoofVolume, SkillionWedgeIsHalfTheBox) {
    EXPECT_NEAR(roofVolume(roofed(rectangle(20, 10), RoofShape::Skillion, kMin, kHeight, kRoof)), 20 * 10 * kRoof / 2, 1e-3);
}

TEST(RoofVolume, PyramidIsAThirdOfThePrism) {
    EXPECT_NEAR(roofVolume(roofed(rectangle(10, 10), RoofShape::Pyramidal, kMin, kHeight, kRoof)), 100 * kRoof / 3, 1e-3);
    // On a hexagon too (apex at the centroid).
    const Polygon hexagon = regularPolygon(6, 7);
    EXPECT_NEAR(roofVolume(roofed(hexagon, RoofShape::Pyramidal, kMin, kHeight, kRoof)), ringArea(hexagon.outer) * kRoof / 3, 1e-3);
}

TEST(RoofVolume, HippedRectangleFromTheSkeleton) {
    // Rectangle a x b (a <= b), ridge height H: V = H (ab/2 - a^2/6).
    const double a = 10, b = 20;
    EXPECT_NEAR(roofVolume(roofed(rectangle(b, a), RoofShape::Hipped, kMin, kHeight, kRoof)), kRoof * (a * b / 2 - a * a / 6), 1e-3);
}

TEST(RoofVolume, MansardHasTwoPitches) {
    // Height f(t) of the skeleton time t: 0.65 H over the first quarter of the depth T, then to H.
    // V = sum of slope x integral of the inset area over each piece.
    const double a = 10, b = 20, depth = a / 2, tb = 0.25 * depth;
    const double expected = 0.65 * kRoof / tb * insetAreaIntegral(a, b, 0, tb) +
                            0.35 * kRoof / (depth - tb) * insetAreaIntegral(a, b, tb, depth);
    EXPECT_NEAR(roofVolume(roofed(rectangle(b, a), RoofShape::Mansard, kMin, kHeight, kRoof)), expected, 1e-3);
}

TEST(RoofVolume, GambrelHasTwoPitches) {
    // Across the 10 m span: 0.6 H over the outer quarters of each half, then to H at the ridge.
    const double span = 10, depth = 20, q = 0.25 * span / 2;
    const double profileArea = 2 * (q * 0.6 * kRoof / 2 + (span / 2 - q) * (0.6 * kRoof + kRoof) / 2);
    EXPECT_NEAR(roofVolume(roofed(rectangle(depth, span), RoofShape::Gambrel, kMin, kHeight, kRoof)), profileArea * depth, 1e-3);
}

TEST(RoofVolume, RoundIsAHalfCylinder) {
    // 16 segments inscribed in the half ellipse: area (N/2) sin(pi/N) w/2 H, 0.64% under pi/4 w H.
    const double span = 10, depth = 20, n = 16;
    const double v = roofVolume(roofed(rectangle(depth, span), RoofShape::Round, kMin, kHeight, kRoof));
    EXPECT_NEAR(v, n / 2 * std::sin(std::numbers::pi / n) * span / 2 * kRoof * depth, 1e-3);
    EXPECT_NEAR(v, std::numbers::pi / 4 * span * kRoof * depth, 0.01 * v);
}

TEST(RoofVolume, DomeIsAnEllipsoidCap) {
    // A 64-gon of radius 6 m, dome 6 m high: 2/3 pi r^2 h within 2% (8 rings, 64 sides).
    const double r = 6, h = 6;
    const double v = roofVolume(roofed(regularPolygon(64, r, 3, 4), RoofShape::Dome, kMin, 16.0f, float(h)));
    EXPECT_NEAR(v, 2.0 / 3 * std::numbers::pi * r * r * h, 0.02 * v);
}

TEST(RoofVolume, FlatRoofWithParapet) {
    // A 20 x 10 box 12 m tall: a 0.8-1.2 m parapet 0.3 m thick rings a sunken deck.
    const Building b = roofed(rectangle(20, 10), RoofShape::Flat, kMin, kHeight, 0);
    const CityMesh out = meshOne(b);
    EXPECT_EQ(openEdges(out.mesh), 0u);
    const double box = 200.0 * (kHeight - kMin), sunk = closedVolume(out.mesh);
    // The sunken volume is the inner 19.4 x 9.4 rectangle times the parapet height, in [0.8, 1.2] m.
    const double parapet = (box - sunk) / (19.4 * 9.4);
    EXPECT_GE(parapet, 0.8 - 1e-4);
    EXPECT_LE(parapet, 1.2 + 1e-4);
}
