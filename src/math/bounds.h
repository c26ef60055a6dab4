// Axis-aligned bounding boxes (host+device).
#pragma once

#include "math/vec.h"

#include <cfloat>

namespace urbis {

struct Bounds3f {
    Vec3f lo{FLT_MAX, FLT_MAX, FLT_MAX};
    Vec3f hi{-FLT_MAX, -FLT_MAX, -FLT_MAX};

    URBIS_HD void extend(Vec3f p) { lo = vmin(lo, p); hi = vmax(hi, p); }
    URBIS_HD void extend(const Bounds3f& b) { lo = vmin(lo, b.lo); hi = vmax(hi, b.hi); }
    URBIS_HD bool empty() const { return lo.x > hi.x; }
    URBIS_HD Vec3f extent() const { return hi - lo; }
    URBIS_HD Vec3f centre() const { return (lo + hi) * 0.5f; }
    /// Surface area in m^2; 0 for an empty box.
    URBIS_HD float area() const {
        if (empty()) return 0.0f;
        Vec3f d = extent();
        return 2.0f * (d.x * d.y + d.y * d.z + d.z * d.x);
    }
};

} // namespace urbis
