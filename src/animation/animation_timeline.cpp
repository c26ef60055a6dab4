#include "animation/animation_timeline.h"

#include "astro/civil_time.h"

#include <algorithm>
#include <cmath>

namespace urbis {

namespace {

CivilTime civilTimeOf(const TimeKeyframe& k) {
    std::string error;
    return parseIsoTime(k.date, error).value_or(CivilTime{});   // checked when the file was read
}

/// Seconds from `a` to `b` (UTC instants), to the millisecond: a Julian day of about 2.46e6 carries
/// some 20 microseconds of rounding, which would otherwise make 30 minutes 29:59.99998.
double secondsBetween(const CivilTime& a, const CivilTime& b) {
    return std::round((julianDayUtc(b) - julianDayUtc(a)) * 86400.0 * 1000.0) / 1000.0;
}

/// The keyframes around `seconds` and how far between them it lies (0 at `from`, 1 at `to`); before
/// the first keyframe or after the last, that keyframe twice.
struct Between {
    const TimeKeyframe& from;
    const TimeKeyframe& to;
    double share;
};

Between between(std::span<const TimeKeyframe> keyframes, double seconds) {
    if (seconds <= keyframes.front().time) return {keyframes.front(), keyframes.front(), 0.0};
    if (seconds >= keyframes.back().time) return {keyframes.back(), keyframes.back(), 0.0};
    const auto next = std::upper_bound(keyframes.begin(), keyframes.end(), seconds,
                                       [](double t, const TimeKeyframe& k) { return t < k.time; });
    const TimeKeyframe& from = *(next - 1);
    return {from, *next, (seconds - from.time) / (next->time - from.time)};
}

} // namespace

float exposureAt(std::span<const TimeKeyframe> keyframes, double seconds) {
    const Between b = between(keyframes, seconds);
    return *b.from.exposure + (*b.to.exposure - *b.from.exposure) * float(b.share);
}

std::string dateAt(std::span<const TimeKeyframe> keyframes, double seconds) {
    const Between b = between(keyframes, seconds);
    if (b.share == 0.0) return b.from.date;   // a keyframe's own text
    const CivilTime from = civilTimeOf(b.from);
    return formatIsoTime(civilTimeAfter(from, b.share * secondsBetween(from, civilTimeOf(b.to))));
}

uint32_t frameCountOf(const AnimationDescription& a) {
    double duration = a.duration;
    if (duration <= 0) {
        if (!a.camera.empty()) duration = std::max(duration, a.camera.back().time);
        if (!a.time.empty()) duration = std::max(duration, a.time.back().time);
    }
    // The small allowance keeps the frame at exactly the duration (3 s at 24 fps: frame 72).
    return uint32_t(std::floor(duration * double(a.fps) + 1e-6)) + 1;
}

AnimationTimeline::AnimationTimeline(const SceneDescription& scene, const GeoOrigin& origin)
    : scene_(scene), camera_(scene.animation.camera, scene.camera, origin) {}

SceneDescription AnimationTimeline::frame(uint32_t frame) const {
    SceneDescription d = scene_;
    const double seconds = secondsOf(frame);
    if (!d.animation.camera.empty()) d.camera = camera_.at(seconds);
    if (!d.animation.time.empty()) d.astronomy.time = dateAt(d.animation.time, seconds);
    if (!d.animation.time.empty() && d.animation.time.front().exposure) d.film.exposure = exposureAt(d.animation.time, seconds);
    return d;
}

} // namespace urbis
