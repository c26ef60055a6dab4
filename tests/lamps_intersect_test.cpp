// The analytic lamp: rays hit its pole at the analytic distance, miss beside it, meet the glass from
// below and the globe from above, keep their precision from far away; the record's bounds hold its
// twin; the scene's trace reports the lamp kind with its object, part and material; and the light's
// colour follows its temperature.
#include "geometry/scene_intersect.h"
#include "scene/lamp_emission.h"
#include "scene/lamp_pieces.h"
#include "scene/scene.h"
#include "streets/lamp_mesher.h"
#include "streets/street_lamps.h"

#include <gtest/gtest.h>

using namespace urbis;

namespace {

LampRecord postTop(LampShape shape, Vec3f base) {
    LampRecord l;
    l.base = base;
    l.height = 5.0f;
    l.poleRadius = 0.1f;
    l.armLength = 0.0f;
    l.shape = shape;
    l.headSize = 0.5f;
    l.object = 7;
    l.material = 20;
    return l;
}

bool hitLamp(const LampRecord& l, Ray ray, LampHit& hit) { return intersectLamp(l, ray, hit, false); }

/// The pole's radius at height y: it narrows by kLampPoleSlope per metre.
float poleRadiusAt(const LampRecord& l, float y) { return l.poleRadius + kLampPoleSlope * y; }

} // namespace

TEST(LampIntersect, RayHitsThePoleAtTheAnalyticDistance) {
    const LampRecord l = postTop(LampShape::Globe, {10.0f, 0.0f, -5.0f});
    LampHit hit;
    ASSERT_TRUE(hitLamp(l, {{0.0f, 2.0f, -5.0f}, {1.0f, 0.0f, 0.0f}}, hit));
    EXPECT_NEAR(hit.t, 10.0f - poleRadiusAt(l, 2.0f), 1e-5f);
    EXPECT_EQ(hit.piece, 0u);
    EXPECT_EQ(hit.face, 0u);
    // Off the axis by half the radius: the chord's near end.
    const float r = poleRadiusAt(l, 2.0f), off = 0.5f * r;
    ASSERT_TRUE(hitLamp(l, {{0.0f, 2.0f, -5.0f + off}, {1.0f, 0.0f, 0.0f}}, hit));
    EXPECT_NEAR(hit.t, 10.0f - std::sqrt(r * r - off * off), 2e-5f);
}

TEST(LampIntersect, RayBesideThePoleMisses) {
    const LampRecord l = postTop(LampShape::Globe, {10.0f, 0.0f, -5.0f});
    LampHit hit;
    EXPECT_FALSE(hitLamp(l, {{0.0f, 2.0f, -5.0f + 1.01f * l.poleRadius}, {1.0f, 0.0f, 0.0f}}, hit));
    EXPECT_FALSE(hitLamp(l, {{0.0f, 2.0f, -5.3f}, {1.0f, 0.0f, 0.0f}}, hit));
    // Above the lamp, and a ray that ends before the pole.
    EXPECT_FALSE(hitLamp(l, {{0.0f, 9.0f, -5.0f}, {1.0f, 0.0f, 0.0f}}, hit));
    EXPECT_FALSE(hitLamp(l, {{0.0f, 2.0f, -5.0f}, {1.0f, 0.0f, 0.0f}, 0.0f, 9.0f}, hit));
}

TEST(LampIntersect, FarRaysKeepThePolesPrecision) {
    const LampRecord l = postTop(LampShape::Globe, {1500.0f, 0.0f, -800.0f});
    const Vec3f origin{-500.0f, 300.0f, 400.0f}, target{1500.0f, 1.5f, -800.0f};
    const Vec3f dir = normalize(target - origin);
    LampHit hit;
    ASSERT_TRUE(hitLamp(l, {origin, dir}, hit));
    EXPECT_EQ(hit.piece, 0u);
    // The hit lies on the pole's surface, within a millimetre.
    const Vec3f p = origin + dir * hit.t;
    const float radial = std::hypot(p.x - l.base.x, p.z - l.base.z);
    EXPECT_NEAR(radial, poleRadiusAt(l, p.y), 1e-3f);
}

TEST(LampIntersect, GlassIsHitFromBelowAndTheGlobeFromAbove) {
    for (LampShape shape : {LampShape::Cobra, LampShape::Cone, LampShape::Flat, LampShape::Lantern}) {
        LampRecord l = postTop(shape, {0.0f, 0.0f, 0.0f});
        l.armLength = shape == LampShape::Cobra || shape == LampShape::Flat ? 1.5f : 0.0f;
        l.armX = 0.6f;
        l.armZ = 0.8f;
        // Under the glass's centre, beside the pole where the head is on it: straight up.
        const float off = l.armLength > 0.0f ? 0.0f : 0.2f * l.headSize;
        const LampPiece glass = lampPiece(l, 3);
        const Vec3f under = l.worldFromLamp({glass.a.x, 1.0f, glass.a.z}) + l.sideAxis() * off;
        LampHit hit;
        ASSERT_TRUE(hitLamp(l, {under, {0.0f, 1.0f, 0.0f}}, hit)) << int(shape);
        EXPECT_EQ(lampPiece(l, int(hit.piece)).part, SurfacePart::LampGlass) << int(shape);
    }
    const LampRecord globe = postTop(LampShape::Globe, {3.0f, 0.0f, 4.0f});
    const LampPiece sphere = lampPiece(globe, 3);
    ASSERT_EQ(sphere.shape, LampPieceShape::Sphere);
    LampHit hit;
    ASSERT_TRUE(hitLamp(globe, {{3.0f, 20.0f, 4.0f}, {0.0f, -1.0f, 0.0f}}, hit));
    EXPECT_EQ(hit.piece, 3u);
    EXPECT_NEAR(hit.t, 20.0f - (sphere.a.y + sphere.b.x), 1e-5f);
}

TEST(LampIntersect, BoundsHoldTheTwinOfEveryShapeAndMount) {
    for (LampHead head : {LampHead::Cobra, LampHead::Globe, LampHead::Lantern, LampHead::Cone, LampHead::Flat})
        for (LampMount mount : {LampMount::Pole, LampMount::BentMast, LampMount::Wall, LampMount::Suspended}) {
            Lamp lamp;
            lamp.position = {120.0, -40.0};
            lamp.head = head;
            lamp.mount = mount;
            lamp.direction = 33.0f;
            const LampRecord r = lampRecordOf(lamp, 5, 0);
            TriangleMesh mesh;
            ASSERT_GT(meshLamp(r, mesh), 20u);
            const Bounds3f b = primBounds(r);
            for (const Triangle& t : mesh.triangles)
                for (Vec3f p : {t.p0, t.p1, t.p2})
                    for (int a = 0; a < 3; ++a) {
                        EXPECT_GE(p[a], b.lo[a]);
                        EXPECT_LE(p[a], b.hi[a]);
                    }
        }
}

TEST(LampIntersect, SceneTraceReportsTheLampKindObjectPartAndMaterial) {
    std::vector<LampRecord> lamps = {postTop(LampShape::Lantern, {0.0f, 0.0f, 0.0f}),
                                     postTop(LampShape::Globe, {4.0f, 0.0f, 0.0f})};
    lamps[1].object = 8;
    const Scene scene = Scene::build({.materials = std::vector<Material>(24),
                                      .grounds = {GroundRecord::around(0, 0, 0, 1)}, .lamps = lamps});
    const SceneView view = scene.view();
    EXPECT_TRUE(view.costlyLeaves);
    ASSERT_EQ(scene.lamps.size(), 2u);
    const SurfaceHit pole = intersectScene(view, {{4.0f, 1.0f, -10.0f}, {0.0f, 0.0f, 1.0f}});
    ASSERT_TRUE(pole.valid());
    EXPECT_EQ(pole.kind, kPrimKindOf<LampRecord>);
    EXPECT_EQ(pole.object, 8u);
    EXPECT_EQ(pole.part, SurfacePart::LampPole);
    EXPECT_EQ(pole.material, 20u + uint32_t(LampMaterial::Metal));
    EXPECT_NEAR(pole.normal.z, -1.0f, 1e-4f);   // the pole narrows: its normal tilts up a little
    EXPECT_NEAR(pole.uv.x, 1.0f, 1e-5f);   // metres up the pole
    EXPECT_NEAR(length(pole.frame().x), 1.0f, 1e-5f);
    const SurfaceHit glass = intersectScene(view, {{0.0f, 5.1f, -10.0f}, {0.0f, 0.0f, 1.0f}});
    ASSERT_TRUE(glass.valid());
    EXPECT_EQ(glass.object, 7u);
    EXPECT_EQ(glass.part, SurfacePart::LampGlass);
    EXPECT_EQ(glass.material, 20u + uint32_t(LampMaterial::Glass));
    EXPECT_TRUE(occludedScene(view, {{0.0f, 5.1f, -10.0f}, {0.0f, 0.0f, 1.0f}}));
    EXPECT_FALSE(occludedScene(view, {{2.0f, 3.0f, -10.0f}, {0.0f, 0.0f, 1.0f}}));
}

TEST(LampEmission, BlackbodyColourFollowsTheTemperature) {
    const Vec3f sodium = blackbodyRgb(2000.0f), led = blackbodyRgb(4000.0f), day = blackbodyRgb(6500.0f);
    for (Vec3f c : {sodium, led, day}) EXPECT_NEAR(luminance(c), 1.0f, 1e-4f);
    EXPECT_GT(sodium.x, sodium.y);
    EXPECT_GT(sodium.y, sodium.z);
    EXPECT_LT(sodium.z / sodium.x, led.z / led.x);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(day[c], 1.0f, 0.1f) << c;   // near D65's white
    EXPECT_GT(blackbodyRgb(12000.0f).z, blackbodyRgb(12000.0f).x);
}

TEST(LampEmission, LightByMethodAndTaggedTemperature) {
    EXPECT_EQ(lampLightOf("high_pressure_sodium").colourTemperature, 2000.0f);
    EXPECT_EQ(lampLightOf("LED").colourTemperature, 4000.0f);
    EXPECT_EQ(lampLightOf("gaslight").colourTemperature, 2200.0f);
    Lamp lamp;
    lamp.lampType = "sodium";
    lamp.lightCount = 2;
    EXPECT_EQ(lampRecordOf(lamp, 1, 0).colourTemperature, 2000.0f);
    EXPECT_EQ(lampRecordOf(lamp, 1, 0).luminousFlux, 30000.0f);
    lamp.colourTemperature = 3000.0f;
    EXPECT_EQ(lampRecordOf(lamp, 1, 0).colourTemperature, 3000.0f);
}
