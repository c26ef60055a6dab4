#include "scene/camera_framing.h"

#include "lights/sun.h"
#include "math/sampling.h"

#include <algorithm>

namespace urbis {

Camera frameCity(const Bounds3f& cityBounds, float fovYDeg, float aspect) {
    Bounds3f b = cityBounds;
    if (b.empty()) b = Bounds3f{Vec3f{-50, 0, -50}, Vec3f{50, 20, 50}};
    const Vec3f centre = b.centre();
    const Vec3f towardsCamera = directionFromElevationAzimuth(22.0f, 225.0f);
    // The view's orientation does not depend on where the camera stands: take it from one 1 m away.
    const Camera oriented = makeLookAtCamera(centre + towardsCamera, centre, fovYDeg, aspect);
    const float tanY = oriented.tanHalfFovY * (1.0f - kFramingMargin);
    const float tans[2] = {tanY * aspect, tanY};
    const Vec3f axes[2] = {oriented.right, oriented.up};
    // The camera stands at centre + a right + c up - d forward. A corner q (relative to the centre) has
    // depth q.f + d, and lies inside the image across an axis when |q.axis - shift| <= tan (q.f + d):
    // shift >= q.axis - tan q.f - tan d and shift <= q.axis + tan q.f + tan d over all corners. The least
    // d that leaves room for a shift is (max(q.axis - tan q.f) - min(q.axis + tan q.f)) / (2 tan), and
    // the shift halfway between the bounds centres the corners on that axis.
    // Every corner at least 1 m in front of the camera puts all of the (convex) box in front of it.
    float distance = 0.0f, shift[2] = {0.0f, 0.0f};
    for (int k = 0; k < 2; ++k) {
        float lower = -1e30f, upper = 1e30f;
        for (int i = 0; i < 8; ++i) {
            const Vec3f q = Vec3f{i & 1 ? b.hi.x : b.lo.x, i & 2 ? b.hi.y : b.lo.y, i & 4 ? b.hi.z : b.lo.z} - centre;
            const float along = dot(q, axes[k]), depth = dot(q, oriented.forward);
            lower = std::max(lower, along - tans[k] * depth);
            upper = std::min(upper, along + tans[k] * depth);
            distance = std::max(distance, 1.0f - depth);
        }
        distance = std::max(distance, (lower - upper) / (2.0f * tans[k]));
        shift[k] = 0.5f * (lower + upper);
    }
    const Vec3f position = centre + axes[0] * shift[0] + axes[1] * shift[1] - oriented.forward * distance;
    return makeLookAtCamera(position, position + oriented.forward, fovYDeg, aspect);
}

Camera cameraFromHeading(Vec3f position, float headingDeg, float pitchDeg, float fovYDeg, float aspect) {
    return makeLookAtCamera(position, position + directionFromElevationAzimuth(pitchDeg, headingDeg), fovYDeg, aspect);
}

} // namespace urbis
