#include "animation/camera_path.h"

#include "base/input_error.h"
#include "math/catmull_rom.h"
#include "math/constants.h"
#include "osm/geo_projection.h"
#include "scene/sun.h"

#include <algorithm>
#include <cmath>

namespace urbis {

namespace {

constexpr float kDegrees = 180.0f / kPi;

/// Heading (degrees clockwise from north) and pitch (above the horizon) of a direction.
Vec3f anglesOf(Vec3f dir) {
    const Vec3f d = normalize(dir);
    return {std::atan2(d.x, -d.z) * kDegrees, std::asin(std::clamp(d.y, -1.0f, 1.0f)) * kDegrees, 0.0f};
}

} // namespace

float eased(float u, Easing ease) {
    switch (ease) {
    case Easing::EaseIn: return u * u;                        // leaves the keyframe at rest
    case Easing::EaseOut: return u * (2.0f - u);              // arrives at rest
    case Easing::EaseInOut: return u * u * (3.0f - 2.0f * u); // smoothstep
    case Easing::Linear: break;
    }
    return u;
}

CameraPath::CameraPath(std::span<const CameraKeyframe> keyframes, const CameraDescription& camera, const GeoOrigin& origin) {
    for (size_t i = 0; i < keyframes.size(); ++i) {
        const CameraKeyframe& k = keyframes[i];
        const std::string where = "animation.camera[" + std::to_string(i) + "]";
        Pose pose{k.time, {}, {}, {}, Easing::Linear};
        if (k.position) {
            pose.position = *k.position;
        } else {
            if (!k.geo || !origin.valid) throw InputError(where + ".geo: needs a city imported from source.osm (--osm)");
            const auto [lon, lat, altitude] = *k.geo;
            const Vec2d local = GeoProjection(LonLat{origin.lon, origin.lat}).project(LonLat{lon, lat});
            pose.position = {float(local.x), float(altitude), float(-local.y)};
        }
        if (k.heading) {
            byTarget_ = false;
            pose.angles = {*k.heading, *k.pitch, 0.0f};
            pose.target = pose.position + directionFromElevationAzimuth(*k.pitch, *k.heading) * kLookDistance;
        } else {
            if (!k.target && !camera.target) throw InputError(where + ": needs a target, or heading and pitch (camera.target is unset)");
            pose.target = k.target ? *k.target : *camera.target;
            pose.angles = anglesOf(pose.target - pose.position);
        }
        pose.angles.z = k.fov.value_or(camera.fov);
        pose.ease = k.ease;
        if (!poses_.empty()) {   // the heading the short way round from the keyframe before
            const float before = poses_.back().angles.x;
            pose.angles.x -= 360.0f * std::round((pose.angles.x - before) / 360.0f);
        }
        poses_.push_back(pose);
    }
}

CameraDescription CameraPath::at(double seconds) const {
    CameraDescription out;
    if (poses_.empty()) return out;
    // The segment [i, i + 1] holding `seconds`, or a keyframe of its own at either end.
    size_t i = size_t(std::upper_bound(poses_.begin(), poses_.end(), seconds,
                                       [](double t, const Pose& p) { return t < p.time; }) - poses_.begin());
    i = i == 0 ? 0 : i - 1;
    const size_t last = poses_.size() - 1;
    const size_t j = std::min(i + 1, last);
    const Pose& a = poses_[i];
    const Pose& b = poses_[j];
    const float u = j == i ? 0.0f : eased(std::clamp(float((seconds - a.time) / (b.time - a.time)), 0.0f, 1.0f), a.ease);
    const auto spline = [&](Vec3f Pose::*field, float alpha) {
        const Vec3f p1 = a.*field, p2 = b.*field;
        const Vec3f p0 = i > 0 ? poses_[i - 1].*field : mirroredEnd(p1, p2);
        const Vec3f p3 = j < last ? poses_[j + 1].*field : mirroredEnd(p2, p1);
        return catmullRom(p0, p1, p2, p3, u, alpha);
    };
    const Vec3f position = spline(&Pose::position, 0.5f);
    const Vec3f angles = spline(&Pose::angles, 0.0f);
    out.position = position;
    out.target = byTarget_ ? spline(&Pose::target, 0.5f)
                           : position + directionFromElevationAzimuth(angles.y, angles.x) * kLookDistance;
    out.fov = std::clamp(angles.z, 1.0f, 170.0f);
    return out;
}

} // namespace urbis
