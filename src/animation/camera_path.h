// The camera of an animation at any instant: its keyframes resolved into world metres and joined by
// centripetal Catmull-Rom splines (math/catmull_rom.h), each segment run through with its keyframe's
// easing. docs/animation.md.
#pragma once

#include "description/animation_description.h"
#include "description/scene_description.h"
#include "model/city_model.h"

#include <span>
#include <vector>

namespace urbis {

/// Metres from the camera to the target that a heading and pitch stand for in a CameraDescription.
inline constexpr float kLookDistance = 100.0f;

class CameraPath {
public:
    /// Resolves `keyframes` (times increasing, as animationFromJson checks): geo keyframes around the
    /// city's `origin`; a keyframe without a look takes `camera.target`, without a fov `camera.fov`.
    /// Throws InputError where a keyframe cannot be placed (geo without a valid origin, no look and
    /// no camera.target); firstSceneProblem rules both out for a checked description.
    CameraPath(std::span<const CameraKeyframe> keyframes, const CameraDescription& camera, const GeoOrigin& origin);

    /// The camera at `seconds` as a description (position, target and fov; no geo): a keyframe's own
    /// at its time, the first one's before it and the last one's after it. The position (and the
    /// target, where every keyframe names one) follow the centripetal spline; otherwise the look
    /// follows heading and pitch (the heading the short way round) on the uniform spline, as the fov does.
    CameraDescription at(double seconds) const;

private:
    struct Pose {
        double time;
        Vec3f position, target;
        Vec3f angles;   ///< heading (unwrapped: within 180 of the one before), pitch, fov; degrees
        Easing ease;
    };
    std::vector<Pose> poses_;
    bool byTarget_ = true;   ///< every keyframe looks at a point: the target is splined
};

/// `u` in [0, 1] run through by `ease`: 0 and 1 stay put.
float eased(float u, Easing ease);

} // namespace urbis
