#include "scene/camera_framing.h"

#include "scene/sun.h"
#include "math/sampling.h"

#include <algorithm>
#include <vector>

namespace urbis {

Camera frameCity(const Bounds3f& cityBounds, float fovYDeg, float aspect) {
    return frameCity(std::span<const Bounds3f>(&cityBounds, 1), fovYDeg, aspect);
}

Camera frameCity(std::span<const Bounds3f> pieces, float fovYDeg, float aspect) {
    std::vector<Bounds3f> kept;
    Bounds3f b;
    for (const Bounds3f& piece : pieces)
        if (!piece.empty()) kept.push_back(piece), b.extend(piece);
    if (kept.empty()) kept = {b = Bounds3f{Vec3f{-50, 0, -50}, Vec3f{50, 20, 50}}};
    const Vec3f centre = b.centre();
    const Vec3f towardsCamera = directionFromElevationAzimuth(22.0f, 225.0f);
    // The view's orientation does not depend on where the camera stands: take it from one 1 m away.
    const Camera oriented = makeLookAtCamera(centre + towardsCamera, centre, fovYDeg, aspect);
    const float tanY = oriented.tanHalfFovY * (1.0f - kFramingMargin);
    const float tans[2] = {tanY * aspect, tanY};
    const Vec3f axes[2] = {oriented.right, oriented.up};
    std::vector<Vec3f> corners;
    corners.reserve(8 * kept.size());
    for (const Bounds3f& piece : kept)
        for (int i = 0; i < 8; ++i)
            corners.push_back(Vec3f{i & 1 ? piece.hi.x : piece.lo.x, i & 2 ? piece.hi.y : piece.lo.y,
                                    i & 4 ? piece.hi.z : piece.lo.z} - centre);
    // The camera stands at centre + a right + c up - d forward. A corner q (relative to the centre) has
    // depth q.f + d, and lies inside the image across an axis when |q.axis - shift| <= tan (q.f + d):
    // shift >= q.axis - tan q.f - tan d and shift <= q.axis + tan q.f + tan d over all corners. The least
    // d that leaves room for a shift is (max(q.axis - tan q.f) - min(q.axis + tan q.f)) / (2 tan).
    // Every corner at least 1 m in front of the camera puts all of the (convex) box in front of it.
    float distance = 0.0f, lower[2], upper[2];
    for (int k = 0; k < 2; ++k) {
        lower[k] = -1e30f, upper[k] = 1e30f;
        for (const Vec3f& q : corners) {
            const float along = dot(q, axes[k]), depth = dot(q, oriented.forward);
            lower[k] = std::max(lower[k], along - tans[k] * depth);
            upper[k] = std::min(upper[k], along + tans[k] * depth);
            distance = std::max(distance, 1.0f - depth);
        }
        distance = std::max(distance, (lower[k] - upper[k]) / (2.0f * tans[k]));
    }
    // Within the shifts that keep every corner inside, the one where the corners reach as far past the
    // image centre on one side as on the other (their film extent's sum, falling with the shift, is 0).
    Vec3f position = centre - oriented.forward * distance;
    for (int k = 0; k < 2; ++k) {
        float lo = lower[k] - tans[k] * distance, hi = upper[k] + tans[k] * distance;
        for (int step = 0; step < 40; ++step) {
            const float shift = 0.5f * (lo + hi);
            float most = -1e30f, least = 1e30f;
            for (const Vec3f& q : corners) {
                const float film = (dot(q, axes[k]) - shift) / (dot(q, oriented.forward) + distance);
                most = std::max(most, film);
                least = std::min(least, film);
            }
            (most + least > 0.0f ? lo : hi) = shift;
        }
        position += axes[k] * (0.5f * (lo + hi));
    }
    return makeLookAtCamera(position, position + oriented.forward, fovYDeg, aspect);
}

Camera cameraFromHeading(Vec3f position, float headingDeg, float pitchDeg, float fovYDeg, float aspect) {
    return makeLookAtCamera(position, position + directionFromElevationAzimuth(pitchDeg, headingDeg), fovYDeg, aspect);
}

} // namespace urbis
