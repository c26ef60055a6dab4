// An animation's frames and the scene description of each: the scene file's description with the
// camera and the date and time of that frame's instant (docs/animation.md).
#pragma once

#include "animation/camera_path.h"
#include "description/scene_description.h"
#include "model/city_model.h"

#include <cstdint>
#include <span>
#include <string>

namespace urbis {

/// The film's exposure at `seconds`, in stops: linear between the time keyframes around it (which
/// all give one), the first one's before it and the last one's after it.
float exposureAt(std::span<const TimeKeyframe> keyframes, double seconds);

/// astronomy.time at `seconds`: the instant interpolated linearly between the keyframes around it,
/// written on the clock (UTC offset) of the earlier one; the first keyframe's date before it, the
/// last one's after it. `keyframes` are checked (animationFromJson) and not empty.
std::string dateAt(std::span<const TimeKeyframe> keyframes, double seconds);

/// Frames 0 .. N - 1 at 0, 1 / fps, ... up to the duration (animation.duration, or the last
/// keyframe's time): N of them.
uint32_t frameCountOf(const AnimationDescription& animation);

class AnimationTimeline {
public:
    /// The timeline of `scene.animation` (checked: firstSceneProblem), geo keyframes placed around
    /// the city's `origin`. Throws InputError as CameraPath does.
    AnimationTimeline(const SceneDescription& scene, const GeoOrigin& origin);

    uint32_t frameCount() const { return frameCountOf(scene_.animation); }
    double secondsOf(uint32_t frame) const { return double(frame) / double(scene_.animation.fps); }

    /// The scene of `frame`: the camera of the camera path (where there are camera keyframes) and the
    /// date and time (and exposure, where they give one) of the time keyframes (where there are), the
    /// rest as the scene file has it.
    SceneDescription frame(uint32_t frame) const;

private:
    SceneDescription scene_;
    CameraPath camera_;
};

} // namespace urbis
