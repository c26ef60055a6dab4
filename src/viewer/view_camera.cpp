#include "viewer/view_camera.h"

#include "math/constants.h"

#include <algorithm>
#include <cmath>

namespace urbis {

namespace {

constexpr float kRadians = kPi / 180.0f;

/// Unit vector towards `heading`, level: north (-z) at 0, east (+x) at 90.
Vec3f levelForward(float heading) { return {std::sin(heading * kRadians), 0.0f, -std::cos(heading * kRadians)}; }
/// Unit vector to the right of `heading`, level.
Vec3f levelRight(float heading) { return {std::cos(heading * kRadians), 0.0f, std::sin(heading * kRadians)}; }

} // namespace

Vec3f viewForward(const ViewCamera& c) {
    const float cp = std::cos(c.pitch * kRadians);
    return levelForward(c.heading) * cp + Vec3f{0.0f, std::sin(c.pitch * kRadians), 0.0f};
}

Vec3f viewTarget(const ViewCamera& c) { return c.position + viewForward(c) * c.pivotDistance; }

ViewCamera viewCameraLookingAt(Vec3f position, Vec3f target) {
    const Vec3f d = target - position;
    const float horizontal = std::sqrt(d.x * d.x + d.z * d.z);
    ViewCamera c;
    c.position = position;
    c.heading = std::atan2(d.x, -d.z) / kRadians;
    c.pitch = std::clamp(std::atan2(d.y, horizontal) / kRadians, -89.0f, 89.0f);
    c.pivotDistance = std::max(length(d), 1e-3f);
    return c;
}

ViewCamera viewCameraOverlooking(Vec3f target, float heading, float pitch, float distance) {
    ViewCamera c;
    c.heading = heading;
    c.pitch = std::clamp(pitch, -89.0f, 89.0f);
    c.pivotDistance = distance;
    c.position = target - viewForward(c) * distance;
    return c;
}

float CameraController::heightAboveGround() const {
    return std::min(probe_(camera_.position, Vec3f{0, -1, 0}, 1e5f), 1e5f);
}

Vec3f CameraController::cleared(Vec3f p) const {
    if (!collide) return p;
    // A sphere of kClearance about the camera, tested by six short rays: a move along a wall, which
    // the ray of the move itself never meets, is pushed off it too. The ground (down) first.
    constexpr Vec3f kAxes[] = {{0, -1, 0}, {0, 1, 0}, {-1, 0, 0}, {1, 0, 0}, {0, 0, -1}, {0, 0, 1}};
    for (const Vec3f& axis : kAxes)
        if (const float hit = probe_(p, axis, kClearance); hit < kClearance) p = p - axis * (kClearance - hit);
    return p;
}

Vec3f CameraController::reachable(Vec3f to) const {
    if (!collide) return to;
    const Vec3f from = camera_.position, d = to - from;
    const float len = length(d);
    if (len > 0.0f) {
        const Vec3f dir = d / len;
        const float hit = probe_(from, dir, len + kClearance);
        if (hit < len + kClearance) to = from + dir * std::max(0.0f, hit - kClearance);
    }
    return cleared(to);
}

void CameraController::saveForUndo() {
    if (undo_.size() == kMaxUndo) undo_.erase(undo_.begin());
    undo_.push_back(camera_);
}

bool CameraController::update(const CameraInput& in) {
    if (in.scroll != 0.0f) speed = std::clamp(speed * std::pow(kScrollFactor, in.scroll), 1e-3f, 1e3f);
    const bool keys = in.forward || in.back || in.left || in.right || in.up || in.down;
    const bool turning = in.dragging && (in.mouseDx != 0.0f || in.mouseDy != 0.0f);
    const bool active = keys || in.dragging;
    if (active && !moving_) saveForUndo();
    moving_ = active;
    if (!keys && !turning) return false;

    const ViewCamera before = camera_;
    if (turning) {
        const Vec3f pivot = viewTarget(camera_);
        camera_.heading = std::remainder(camera_.heading + in.mouseDx * kDegreesPerPixel, 360.0f);
        camera_.pitch = std::clamp(camera_.pitch - in.mouseDy * kDegreesPerPixel, -89.0f, 89.0f);
        if (mode == CameraMode::Orbit) camera_.position = reachable(pivot - viewForward(camera_) * camera_.pivotDistance);
    }
    if (keys) {
        const float metresPerSecond = speed * std::max(heightAboveGround(), kMinSpeedHeight);
        const Vec3f ahead = mode == CameraMode::Fly ? viewForward(camera_) : levelForward(camera_.heading);
        const float f = float(in.forward) - float(in.back), r = float(in.right) - float(in.left);
        const float u = float(in.up) - float(in.down);
        Vec3f move = ahead * f + levelRight(camera_.heading) * r + Vec3f{0, u, 0};
        if (length(move) > 0.0f) camera_.position = reachable(camera_.position + normalize(move) * (metresPerSecond * in.seconds));
    }
    const Vec3f a = before.position, b = camera_.position;
    return a.x != b.x || a.y != b.y || a.z != b.z || before.heading != camera_.heading || before.pitch != camera_.pitch;
}

void CameraController::jumpTo(const ViewCamera& camera) {
    saveForUndo();
    camera_ = camera;
    camera_.position = cleared(camera.position);  // a jump passes over what lies between
}

bool CameraController::undo() {
    if (undo_.empty()) return false;
    camera_ = undo_.back();
    undo_.pop_back();
    return true;
}

} // namespace urbis
