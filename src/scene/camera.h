// A pinhole camera (host+device POD). World: x east, y up, z south; metres.
#pragma once

#include "math/ray.h"

namespace urbis {

struct Camera {
    Vec3f position;
    Vec3f forward{0, 0, -1};  ///< unit, the view direction
    Vec3f right{1, 0, 0};     ///< unit
    Vec3f up{0, 1, 0};        ///< unit
    float tanHalfFovY = 0.5f; ///< tan of half the vertical field of view
    float aspect = 1.0f;      ///< width / height

    /// The ray through film position (sx, sy) in [0,1)^2, sx to the right, sy downwards.
    URBIS_HD Ray generateRay(float sx, float sy) const {
        float px = (2.0f * sx - 1.0f) * tanHalfFovY * aspect;
        float py = (-2.0f * sy + 1.0f) * tanHalfFovY;
        Ray ray;
        ray.origin = position;
        ray.dir = normalize(up * py + (right * px + forward));
        return ray;
    }
};

/// A camera at `position` looking at `target`, vertical field of view in degrees, y up.
Camera makeLookAtCamera(Vec3f position, Vec3f target, float fovYDeg, float aspect);

} // namespace urbis
