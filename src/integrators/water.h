// Water seen by the path tracer (host+device): the waves' normals on a flat water surface, and the
// absorption along a path below it (docs/water.md).
#pragma once

#include "integrators/bsdf.h"
#include "math/constants.h"

namespace urbis {

/// Gerstner waves summed for the surface's normal. Eight is where the pattern stops repeating visibly.
inline constexpr int kWaterWaves = 8;

/// The mean-square slope of the sea surface under a wind of `speed` m/s: Cox and Munk's clean-surface
/// fit (Cox and Munk 1954, "Measurement of the roughness of the sea surface from photographs of the
/// sun's glitter", JOSA 44(11)) without its calm-sea constant, so a calm water is a mirror.
URBIS_HD inline float waterSlopeVariance(float speed) { return 0.00512f * speed; }

/// The wavelength in metres of the waves of peak energy under a wind of `speed` m/s: Pierson and
/// Moskowitz's peak, omega_p = 0.855 g / U with deep-water dispersion k = omega^2 / g; half a metre at least.
URBIS_HD inline float waterPeakWavelength(float speed) {
    constexpr float g = 9.81f;
    const float k = 0.855f * 0.855f * g / fmaxf(speed * speed, 1e-6f);
    return fmaxf(0.5f, 2.0f * kPi / k);
}

/// The unit normal of the waves at world (x, z) on a water of `optics` whose geometric normal is +y:
/// a sum of kWaterWaves Gerstner waves (Tessendorf 2001, "Simulating Ocean Water"; Finch, GPU Gems
/// ch. 1, eq. 12, at the undisplaced point), wavelengths falling from the peak's by 0.62 each, their
/// directions spread about the wind's, slopes equal and summing to waterSlopeVariance. Static (no time).
URBIS_HD inline Vec3f waveNormal(const WaterOptics& optics, float x, float z) {
    const float speed = sqrtf(optics.windX * optics.windX + optics.windZ * optics.windZ);
    if (!(speed > 0.0f)) return {0, 1, 0};
    // Each wave's slope k A: a sinusoid of slope amplitude a adds a^2 / 2 to the mean-square slope.
    const float slope = sqrtf(2.0f * waterSlopeVariance(speed) / float(kWaterWaves));
    constexpr float kSteepness = 0.5f;   // Gerstner's Q: sharper crests, flatter troughs
    // Directions about the wind's (radians) and phases (turns): fixed, so the water is deterministic.
    constexpr float kSpread[kWaterWaves] = {0.0f, 0.45f, -0.38f, 0.9f, -0.75f, 0.2f, -1.2f, 1.1f};
    constexpr float kPhase[kWaterWaves] = {0.0f, 0.37f, 0.71f, 0.13f, 0.59f, 0.91f, 0.26f, 0.48f};
    const float cw = optics.windX / speed, sw = optics.windZ / speed;
    float wavelength = waterPeakWavelength(speed);
    Vec3f n{0, 1, 0};
    for (int i = 0; i < kWaterWaves; ++i) {
        const float cs = cosf(kSpread[i]), ss = sinf(kSpread[i]);
        const float dx = cw * cs - sw * ss, dz = sw * cs + cw * ss;
        // The phase in turns, reduced before the sine: city coordinates reach thousands of wavelengths,
        // where the GPU's fast sine loses its accuracy.
        float turns = (dx * x + dz * z) / wavelength + kPhase[i];
        turns -= floorf(turns);
        const float phase = 2.0f * kPi * turns;
        const float c = cosf(phase), s = sinf(phase);
        n.x -= dx * slope * c;
        n.z -= dz * slope * c;
        n.y -= kSteepness * slope * s;
        wavelength *= 0.62f;
    }
    return normalize(n);
}

/// The normal that a Water material scatters about at a hit at `p` with geometric normal `ng` (unit,
/// facing `wo`): the waves' normal on the side of ng, or ng where the waves would face away from wo.
URBIS_HD inline Vec3f waterShadingNormal(const Material& m, Vec3f p, Vec3f ng, Vec3f wo) {
    Vec3f n = waveNormal(m.water, p.x, p.z);
    if (ng.y < 0.0f) n = -n;
    return dot(n, wo) > 0.0f ? n : ng;
}

/// Keeps a direction scattered at a water surface on the side of the geometric normal `ng` it chose
/// (above for a reflection from above, below for a refraction into the water, ...): a wave's tilted
/// normal can send it across the flat surface, which is mirrored back.
URBIS_HD inline Vec3f keepWaterSide(Vec3f dir, Vec3f ng, bool above) {
    const float d = dot(dir, ng);
    return (d > 0.0f) == above ? dir : dir - ng * (2.0f * d);
}

/// What a path below a water surface loses: the absorption of the water it is in (zero in the air).
struct WaterPath {
    Vec3f absorption{0, 0, 0};   ///< 1/m

    /// The fraction of radiance left after `metres` of the path (Beer-Lambert).
    URBIS_HD Vec3f transmittance(float metres) const {
        if (!(maxComponent(absorption) > 0.0f)) return {1, 1, 1};   // in the air, as most paths are: no exponentials
        return {expf(-absorption.x * metres), expf(-absorption.y * metres), expf(-absorption.z * metres)};
    }

    /// After `sample` of a Water material `m` about the shading normal `n` at a hit of geometric
    /// normal `ng` (both facing wo): keeps the direction on the side it chose (keepWaterSide); a
    /// refraction downwards enters the water, one upwards leaves it, a reflection keeps the path where
    /// it was. Returns the next ray's tmin (unit directions): past the water's skipBelow when entering.
    URBIS_HD float scattered(const Material& m, Vec3f n, Vec3f ng, BsdfSample& sample) {
        const bool reflected = dot(sample.dir, n) > 0.0f;
        sample.dir = keepWaterSide(sample.dir, ng, reflected);
        if (reflected) return 0.0f;
        const bool entering = sample.dir.y < 0.0f;
        absorption = entering ? m.water.absorption : Vec3f{0, 0, 0};
        return entering ? m.water.skipBelow / -sample.dir.y : 0.0f;
    }
};

} // namespace urbis
