// The viewer's camera controller driven by made-up input, apart from any window: moves, turns,
// speed by height, collisions with a probe of known shapes (the ground y = 0 and a wall x = 50),
// and undo.
#include "viewer/view_camera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace urbis {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

/// The ground plane y = 0 and, with `wall`, the plane x = 50: distance along the unit `dir`.
float shapesProbe(Vec3f o, Vec3f d, float, bool wall) {
    float t = kInf;
    if (d.y < 0 && o.y >= 0) t = std::min(t, -o.y / d.y);
    if (wall && d.x > 0 && o.x <= 50) t = std::min(t, (50 - o.x) / d.x);
    return t;
}

CameraController controllerAt(Vec3f position, float heading, bool wall = false) {
    ViewCamera c;
    c.position = position;
    c.heading = heading;
    c.pitch = 0;
    c.pivotDistance = 20;
    return CameraController(c, [wall](Vec3f o, Vec3f d, float m) { return shapesProbe(o, d, m, wall); });
}

void expectNear(Vec3f a, Vec3f b, float tolerance) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(ViewCamera, LookingAtRoundTripsThroughHeadingAndPitch) {
    const Vec3f position{10, 30, -5}, target{40, 10, 25};
    const ViewCamera c = viewCameraLookingAt(position, target);
    expectNear(viewTarget(c), target, 1e-3f);
    // North is -z, east +x: looking from the origin to (1, 0, -1) is heading 45 (north-east).
    EXPECT_NEAR(viewCameraLookingAt({0, 0, 0}, {1, 0, -1}).heading, 45.0f, 1e-4f);
    EXPECT_NEAR(viewCameraLookingAt({0, 0, 0}, {0, 1, -1}).pitch, 45.0f, 1e-4f);
}

TEST(ViewCamera, OverlookingLooksDownOnTheTargetFromItsDistance) {
    const Vec3f target{100, 12, -50};
    const ViewCamera c = viewCameraOverlooking(target, 90.0f, -30.0f, 250.0f);   // looking east, down
    expectNear(viewTarget(c), target, 1e-3f);
    EXPECT_NEAR(c.position.y - target.y, 125.0f, 1e-3f);                  // 250 m * sin 30
    EXPECT_NEAR(c.position.x - target.x, -250.0f * std::sqrt(3.0f) / 2, 1e-3f);   // west of it
    EXPECT_NEAR(c.position.z, target.z, 1e-3f);
}

TEST(ViewCamera, ForwardKeyMovesAtSpeedTimesHeightAboveGround) {
    CameraController c = controllerAt({0, 40, 0}, 90);   // looking east, 40 m up
    c.mode = CameraMode::Fly;
    CameraInput in;
    in.forward = true;
    in.seconds = 0.5f;
    EXPECT_TRUE(c.update(in));
    expectNear(c.camera().position, {20, 40, 0}, 1e-3f);   // 1 x 40 m/s for half a second, east
    // Near the ground the speed's height is kMinSpeedHeight.
    CameraController low = controllerAt({0, 2, 0}, 0);
    in.forward = false;
    in.right = true;   // heading north: right is east
    low.update(in);
    expectNear(low.camera().position, {CameraController::kMinSpeedHeight * 0.5f, 2, 0}, 1e-3f);
}

TEST(ViewCamera, ScrollScalesSpeedWithoutMoving) {
    CameraController c = controllerAt({0, 10, 0}, 0);
    CameraInput in;
    in.scroll = 2;
    EXPECT_FALSE(c.update(in));
    EXPECT_NEAR(c.speed, CameraController::kScrollFactor * CameraController::kScrollFactor, 1e-5f);
}

TEST(ViewCamera, OrbitTurnsAboutThePivotAndFlyAboutTheCamera) {
    CameraController orbit = controllerAt({0, 10, 0}, 0);
    const Vec3f pivot = viewTarget(orbit.camera());
    CameraInput drag;
    drag.dragging = true;
    drag.mouseDx = 360;   // 90 degrees at kDegreesPerPixel 0.25
    drag.mouseDy = -40;   // 10 degrees up
    ASSERT_TRUE(orbit.update(drag));
    expectNear(viewTarget(orbit.camera()), pivot, 1e-3f);
    EXPECT_NEAR(orbit.camera().heading, 90.0f, 1e-3f);
    EXPECT_NEAR(orbit.camera().pitch, 10.0f, 1e-3f);

    CameraController fly = controllerAt({0, 10, 0}, 0);
    fly.mode = CameraMode::Fly;
    fly.update(drag);
    expectNear(fly.camera().position, {0, 10, 0}, 0);
    EXPECT_NEAR(fly.camera().heading, 90.0f, 1e-3f);
}

TEST(ViewCamera, MovesStopShortOfWallsUnlessCollisionsAreOff) {
    CameraController c = controllerAt({40, 10, 0}, 90, true);   // 10 m west of the wall x = 50, facing it
    c.mode = CameraMode::Fly;
    CameraInput in;
    in.forward = true;
    in.seconds = 2.0f;   // 20 m at 10 m/s: through the wall
    c.update(in);
    EXPECT_NEAR(c.camera().position.x, 50 - CameraController::kClearance, 1e-3f);
    CameraController through = controllerAt({40, 10, 0}, 90, true);
    through.mode = CameraMode::Fly;
    through.collide = false;
    through.update(in);
    EXPECT_NEAR(through.camera().position.x, 60.0f, 1e-3f);
}

TEST(ViewCamera, AMoveAlongAWallKeepsItsClearance) {
    CameraController c = controllerAt({49.5f, 10, 0}, 0, true);   // half a metre from the wall x = 50, facing north
    c.mode = CameraMode::Fly;
    CameraInput in;
    in.forward = true;
    in.seconds = 1.0f;   // 10 m north, along the wall: the move's own ray never meets it
    c.update(in);
    EXPECT_NEAR(c.camera().position.x, 50 - CameraController::kClearance, 1e-3f);
    EXPECT_NEAR(c.camera().position.z, -10.0f, 1e-3f);
}

TEST(ViewCamera, StaysAboveTheGround) {
    CameraController c = controllerAt({0, 3, 0}, 0);
    CameraInput in;
    in.down = true;
    in.seconds = 10;   // 50 m down
    c.update(in);
    EXPECT_NEAR(c.camera().position.y, CameraController::kClearance, 1e-3f);
    EXPECT_NEAR(c.heightAboveGround(), CameraController::kClearance, 1e-3f);
    // A jump to just above the ground lands kClearance above it.
    ViewCamera low = c.camera();
    low.position = {100, 0.25f, 7};
    c.jumpTo(low);
    expectNear(c.camera().position, {100, CameraController::kClearance, 7}, 1e-3f);
}

TEST(ViewCamera, UndoReturnsToTheCameraBeforeEachMove) {
    CameraController c = controllerAt({0, 10, 0}, 0);
    const ViewCamera start = c.camera();
    CameraInput hold;
    hold.forward = true;
    hold.seconds = 0.1f;
    c.update(hold);   // one move over three frames: one undo step
    c.update(hold);
    c.update(hold);
    const ViewCamera afterFirst = c.camera();
    c.update(CameraInput{});   // released
    c.update(hold);           // a second move
    ASSERT_TRUE(c.undo());
    expectNear(c.camera().position, afterFirst.position, 0);
    ASSERT_TRUE(c.undo());
    expectNear(c.camera().position, start.position, 0);
    EXPECT_FALSE(c.undo());
}

} // namespace
} // namespace urbis
