// The sky's record (host+device POD): an analytic zenith-to-horizon gradient above, a constant
// ground colour below. A uniform sky (all three equal) has a known answer, which the tests use.
// The physically based atmosphere of DESIGN.md replaces it later behind the same lookup
// (lights/sky_light.h), and its importance table is built from whatever that lookup returns.
#pragma once

#include "math/vec.h"

namespace urbis {

struct Sky {
    Vec3f zenith{0.16f, 0.32f, 0.72f};   ///< radiance straight up
    Vec3f horizon{0.62f, 0.74f, 0.92f};  ///< radiance at the horizon
    Vec3f ground{0.20f, 0.19f, 0.18f};   ///< radiance of every direction below the horizon
    float exponent = 0.45f;              ///< shape of the gradient

    /// A sky of the same radiance in every direction.
    URBIS_HD static Sky uniform(Vec3f l) { return Sky{l, l, l, 1.0f}; }
};

} // namespace urbis
