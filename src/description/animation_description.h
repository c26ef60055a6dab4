// The animation of a scene file (docs/animation.md): camera keyframes, time-of-day keyframes and the
// frame rate. animation/camera_path.h and animation/time_of_day_path.h turn them into the scene of
// any instant; description/animation_json.h reads and writes their JSON.
#pragma once

#include "base/choice.h"
#include "math/vec.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace urbis {

/// How the segment from a camera keyframe to the next one is run through (animation/camera_path.h: eased).
enum class Easing { Linear, EaseIn, EaseOut, EaseInOut };
inline constexpr Choice<Easing> kEasings[] = {
    {"linear", Easing::Linear}, {"ease_in", Easing::EaseIn}, {"ease_out", Easing::EaseOut}, {"ease_in_out", Easing::EaseInOut}};

/// Where the camera is at `time` and where it looks. Exactly one of `position` and `geo`; at most
/// one of `target` and heading/pitch (neither: the keyframe looks at the scene's camera.target);
/// `fov` none: the scene's camera.fov.
struct CameraKeyframe {
    double time = 0;                              ///< seconds from the animation's start
    std::optional<Vec3f> position;                ///< world metres
    std::optional<std::array<double, 3>> geo;     ///< LON, LAT degrees and metres of altitude (OSM cities only)
    std::optional<Vec3f> target;                  ///< world metres: the point looked at
    std::optional<float> heading, pitch;          ///< degrees clockwise from north; above the horizon
    std::optional<float> fov;                     ///< vertical field of view, degrees
    Easing ease = Easing::Linear;                 ///< for the segment to the next keyframe
};

/// The date and time of day at `time`: the sun, the sky, the moon, the stars and the lit windows
/// follow; and the film's exposure, which night needs many stops more of than day.
struct TimeKeyframe {
    double time = 0;                  ///< seconds from the animation's start
    std::string date;                 ///< ISO 8601 date and time with its UTC offset (astronomy.time's form)
    std::optional<float> exposure;    ///< stops (film.exposure); on every time keyframe or on none
};

struct AnimationDescription {
    float fps = 24.0f;                    ///< frames per second: frame N stands at N / fps seconds
    double duration = 0;                  ///< seconds; 0: the last keyframe's time
    std::vector<CameraKeyframe> camera;   ///< by increasing time; none: the scene's camera throughout
    std::vector<TimeKeyframe> time;       ///< by increasing time; none: astronomy.time throughout

    bool empty() const { return camera.empty() && time.empty(); }
};

} // namespace urbis
