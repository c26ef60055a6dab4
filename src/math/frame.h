// Orthonormal frames around a normal (host+device).
#pragma once

#include "math/vec.h"

#include <cmath>

namespace urbis {

/// A right-handed orthonormal basis with z along a given unit normal.
struct Frame {
    Vec3f x, y, z;

    /// Duff et al. 2017, "Building an Orthonormal Basis, Revisited" (branchless, no singularity).
    URBIS_HD static Frame fromZ(Vec3f n) {
        float sign = copysignf(1.0f, n.z);
        float a = -1.0f / (sign + n.z);
        float b = n.x * n.y * a;
        return {Vec3f{sign * n.x * n.x * a + 1.0f, sign * b, -sign * n.x}, Vec3f{b, n.y * n.y * a + sign, -n.y}, n};
    }
    /// Local (frame) coordinates to world.
    URBIS_HD Vec3f toWorld(Vec3f v) const { return x * v.x + y * v.y + z * v.z; }
};

} // namespace urbis
