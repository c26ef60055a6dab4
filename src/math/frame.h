// Orthonormal frames around a normal (host+device).
#pragma once

#include "math/kernel_math.h"

namespace urbis {

/// A right-handed orthonormal basis with z along a given unit normal.
struct Frame {
    Vec3f x, y, z;

    /// Duff et al. 2017, "Building an Orthonormal Basis, Revisited" (branchless, no singularity).
    URBIS_HD static Frame fromZ(Vec3f n) {
        float sign = copysignf(1.0f, n.z);
        float a = approxDivide(-1.0f, sign + n.z);
        float b = n.x * n.y * a;
        return {Vec3f{1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x}, Vec3f{b, sign + n.y * n.y * a, -n.y}, n};
    }
    /// Local (frame) coordinates to world.
    URBIS_HD Vec3f toWorld(Vec3f v) const { return x * v.x + y * v.y + z * v.z; }
};

} // namespace urbis
