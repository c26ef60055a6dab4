#include "scene/camera.h"

#include "math/sampling.h"
#include "base/input_error.h"

namespace urbis {

Camera makeLookAtCamera(Vec3f position, Vec3f target, float fovYDeg, float aspect) {
    Vec3f view = target - position;
    if (!(length(view) > 0.0f)) throw InputError("camera: position and target are the same point", FailureKind::Usage);
    if (!(fovYDeg > 0.0f && fovYDeg < 179.0f)) throw InputError("camera: field of view must be in (0, 179) degrees", FailureKind::Usage);
    Camera camera;
    camera.position = position;
    camera.forward = normalize(view);
    Vec3f worldUp{0, 1, 0};
    if (std::fabs(dot(camera.forward, worldUp)) > 0.9999f) worldUp = Vec3f{0, 0, -1};
    camera.right = normalize(cross(camera.forward, worldUp));
    camera.up = cross(camera.right, camera.forward);
    camera.tanHalfFovY = std::tan(0.5f * fovYDeg * kPi / 180.0f);
    camera.aspect = aspect;
    return camera;
}

} // namespace urbis
