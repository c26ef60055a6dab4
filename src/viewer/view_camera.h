// The viewer's camera and what the keyboard and the mouse do to it, as plain code apart from any
// window (tests/view_camera_test.cpp drives it with made-up input): orbit and fly modes, speed by
// the height above the ground, a clearance kept from every surface, an undo of the last move.
#pragma once

#include "math/vec.h"

#include <functional>
#include <vector>

namespace urbis {

/// Where the viewer looks from. World metres (x east, y up, z south); angles in degrees.
struct ViewCamera {
    Vec3f position;
    float heading = 0;        ///< clockwise from north (-z)
    float pitch = 0;          ///< above the horizon, [-89, 89]
    float pivotDistance = 100; ///< metres from the position to the orbit pivot, along the view
};

/// The unit view direction of `camera`.
Vec3f viewForward(const ViewCamera& camera);
/// The point the camera orbits and looks at: position + forward * pivotDistance.
Vec3f viewTarget(const ViewCamera& camera);
/// The camera at `position` looking at `target` (distinct points).
ViewCamera viewCameraLookingAt(Vec3f position, Vec3f target);
/// The camera `distance` metres from `target`, looking at it towards `heading` (degrees clockwise
/// from north) and `pitch` (degrees above the horizon; negative looks down); it orbits `target`.
ViewCamera viewCameraOverlooking(Vec3f target, float heading, float pitch, float distance);

enum class CameraMode { Orbit, Fly };

/// One frame's input, as a window gathers it.
struct CameraInput {
    bool forward = false, back = false, left = false, right = false;   ///< W S A D
    bool up = false, down = false;                                     ///< E Q
    bool dragging = false;    ///< the left mouse button held: the mouse turns the view
    float mouseDx = 0, mouseDy = 0;   ///< pixels moved since the last frame (y downwards)
    float scroll = 0;         ///< wheel steps since the last frame (positive: away from the user)
    float seconds = 0;        ///< since the last frame
};

/// Distance from `origin` along the unit `dir` to the first surface, or a value above `maxDistance`
/// where none is that near. The viewer answers it by tracing the scene (viewProbeOf); tests by shapes.
using CameraProbe = std::function<float(Vec3f origin, Vec3f dir, float maxDistance)>;

/// Turns input into camera moves. Fly: the mouse turns the view about the camera; orbit: about the
/// pivot. WASD move along the view's horizontal axes, E and Q up and down, at `speed` times the
/// height above the ground (at least kMinSpeedHeight metres) per second; the wheel scales `speed`
/// by kScrollFactor a step. With `collide`, a move stops kClearance metres short of any surface and
/// the camera ends kClearance from every surface along the six axes (above the ground below it too).
class CameraController {
public:
    static constexpr float kDegreesPerPixel = 0.25f;
    static constexpr float kMinSpeedHeight = 5.0f;   ///< metres: the speed's height near the ground
    static constexpr float kScrollFactor = 1.25f;
    static constexpr float kClearance = 1.0f;        ///< metres kept from surfaces
    static constexpr size_t kMaxUndo = 64;

    CameraController(ViewCamera camera, CameraProbe probe) : camera_(camera), probe_(std::move(probe)) {}

    /// Applies one frame's input; true when the camera moved (the image must start over). A move
    /// that begins (a key or the button pressed after none) first saves the camera for undo().
    bool update(const CameraInput& input);
    /// Moves to `camera` as one undoable step (a jump, a script's move), cleared of the surfaces about it.
    void jumpTo(const ViewCamera& camera);
    /// Back to the camera before the last move; false when there is none.
    bool undo();

    const ViewCamera& camera() const { return camera_; }
    CameraMode mode = CameraMode::Orbit;
    float speed = 1.0f;       ///< multiple of the height above the ground, per second
    bool collide = true;      ///< keep out of buildings and above the ground

    /// Metres from the camera down to the ground or roof below it (the probe's answer, capped at 1e5).
    float heightAboveGround() const;

private:
    /// `p` moved to kClearance from the surfaces within kClearance of it along the six axes, the
    /// ground below first (with `collide`).
    Vec3f cleared(Vec3f p) const;
    /// `to`, or the point kClearance short of the first surface between the camera and `to`, then cleared.
    Vec3f reachable(Vec3f to) const;
    void saveForUndo();

    ViewCamera camera_;
    CameraProbe probe_;
    std::vector<ViewCamera> undo_;
    bool moving_ = false;     ///< a key or the button was held last frame
};

} // namespace urbis
