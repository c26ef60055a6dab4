// A ray with its valid interval (host+device).
#pragma once

#include "math/vec.h"

namespace urbis {

struct Ray {
    Vec3f origin;
    Vec3f dir;   ///< not necessarily unit length; t is measured in units of |dir|
    float tmin = 0.0f;
    float tmax = 3.0e38f;
};

/// What a closest-hit query returns: the primitive, the distance and barycentrics.
struct Hit {
    uint32_t prim = 0xffffffffu;
    float t = 3.0e38f;
    float u = 0, v = 0;
    URBIS_HD bool valid() const { return prim != 0xffffffffu; }
};

} // namespace urbis
