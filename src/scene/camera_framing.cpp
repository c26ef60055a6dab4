#include "scene/camera_framing.h"

#include "lights/sun.h"
#include "math/sampling.h"

namespace urbis {

Camera frameCity(const Bounds3f& cityBounds, float fovYDeg, float aspect) {
    Bounds3f b = cityBounds;
    if (b.empty()) b = Bounds3f{Vec3f{-50, 0, -50}, Vec3f{50, 20, 50}};
    Vec3f centre = b.centre();
    Vec3f target{centre.x, 0.25f * b.hi.y, centre.z};
    float radius = 0.5f * length(b.extent());
    float halfFov = 0.5f * fminf(fovYDeg, fovYDeg * aspect) * kPi / 180.0f;
    // A city is flat: the sphere bound over-estimates what the view must hold, hence 0.62.
    float distance = 0.62f * radius / std::tan(halfFov);
    Vec3f towardsCamera = directionFromElevationAzimuth(22.0f, 225.0f);
    return makeLookAtCamera(target + towardsCamera * distance, target, fovYDeg, aspect);
}

Camera cameraFromHeading(Vec3f position, float headingDeg, float pitchDeg, float fovYDeg, float aspect) {
    return makeLookAtCamera(position, position + directionFromElevationAzimuth(pitchDeg, headingDeg), fovYDeg, aspect);
}

} // namespace urbis
