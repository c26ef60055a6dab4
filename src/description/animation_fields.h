// The scene file's "animation" object (docs/animation.md): the frame rate, the duration and the two
// arrays of keyframes, for visitSceneFields (description/scene_fields.h). A keyframe's own keys and
// the checks across them are description/animation_json.h's.
#pragma once

#include "description/animation_description.h"
#include "description/scene_field.h"

namespace urbis {

/// The longest animation, in seconds.
inline constexpr double kMaxAnimationSeconds = 1e6;

/// Calls the visitor `v` on every field of `a` (as visitSceneFields does).
template <typename Animation, typename Visitor>
void visitAnimationFields(Animation& a, Visitor& v) {
    v.number({"fps", "--fps", "Frames per second of the scene's animation (docs/animation.md)"}, a.fps, 0.01f, 1000.0f);
    v.number({"duration", "--duration", "Seconds of the animation; 0: the last keyframe's time"}, a.duration, 0.0,
             kMaxAnimationSeconds);
    v.keyframes({"camera", nullptr, "Camera keyframes: time, position or geo, target or heading and pitch, fov, ease"},
                a.camera);
    v.keyframes({"time", nullptr, "Time-of-day keyframes: time, date, exposure"}, a.time);
}

} // namespace urbis
