// The sky's record (host+device POD): either Hillaire's physically based atmosphere (scene/atmosphere.h,
// whose look-up tables are arrays of scene_arrays.h) or the analytic sky: a zenith-to-horizon gradient
// above, a constant ground colour below. A uniform analytic sky (all three equal) has a known answer,
// which the tests use. lights/sky_light.h reads either, and the sky's importance table is built from it.
#pragma once

#include "scene/atmosphere.h"

namespace urbis {

enum class SkyModel : uint32_t { Analytic, Atmosphere };

struct Sky {
    Vec3f zenith{0.16f, 0.32f, 0.72f};   ///< analytic: radiance straight up
    Vec3f horizon{0.62f, 0.74f, 0.92f};  ///< analytic: radiance at the horizon
    Vec3f ground{0.20f, 0.19f, 0.18f};   ///< analytic: radiance of every direction below the horizon
    float exponent = 0.45f;              ///< analytic: shape of the gradient
    SkyModel model = SkyModel::Analytic;
    Atmosphere atmosphere;               ///< the model Atmosphere's medium
    bool aerialPerspective = true;       ///< Atmosphere: path segments take its extinction and in-scattering

    /// An analytic sky of the same radiance in every direction.
    URBIS_HD static Sky uniform(Vec3f l) {
        Sky sky;
        sky.zenith = sky.horizon = sky.ground = l;
        sky.exponent = 1.0f;
        return sky;
    }
};

/// Whether path segments between surfaces cross a medium (media/aerial_perspective.h).
URBIS_HD inline bool hasAerialPerspective(const Sky& sky) {
    return sky.model == SkyModel::Atmosphere && sky.aerialPerspective;
}

} // namespace urbis
