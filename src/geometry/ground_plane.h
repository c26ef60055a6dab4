// The ground: an analytic horizontal plane, intersected exactly. A plane of two huge stored
// triangles would put vertices 1e5 m from every hit and lose the precision that spawned rays need.
#pragma once

#include "math/ray.h"

#include <cstdint>

namespace urbis {

struct GroundPlane {
    float height = 0.0f;      ///< world y of the plane, metres
    uint32_t material = 0;
    bool enabled = false;

    /// Distance along the ray to the plane if within (tmin, tmax), else a negative number.
    URBIS_HD float intersect(const Ray& ray) const {
        if (!enabled || ray.dir.y == 0.0f) return -1.0f;
        float t = (height - ray.origin.y) / ray.dir.y;
        return (t > ray.tmin && t < ray.tmax) ? t : -1.0f;
    }
};

} // namespace urbis
