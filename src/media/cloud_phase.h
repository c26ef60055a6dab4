// The phase function of cloud droplets (host+device): two Henyey-Greenstein lobes, a strong forward
// one (the silver lining towards the sun) and a weak backward one (the glory side), as Hillaire,
// "Physically Based Sky, Atmosphere and Cloud Rendering in Frostbite" (SIGGRAPH 2016 course, § 5.1)
// blends them. Directions are those light travels along: cosTheta = 1 is straight on.
#pragma once

#include "math/constants.h"
#include "math/frame.h"
#include "math/sampling.h"
#include "scene/cloud_layer.h"

namespace urbis {

/// Henyey-Greenstein's phase function (per steradian) of anisotropy `g` at the cosine of the
/// scattering angle; integrates to 1 over the sphere.
URBIS_HD inline float henyeyGreenstein(float g, float cosTheta) {
    const float d = 1.0f + g * g - 2.0f * g * cosTheta;
    return (1.0f - g * g) / (4.0f * kPi * d * sqrtf(fmaxf(d, 1e-12f)));
}

/// The cosine of a scattering angle distributed as Henyey-Greenstein of `g`, from a uniform number
/// (the inverse of its cumulative distribution).
URBIS_HD inline float sampleHenyeyGreensteinCosine(float g, float u) {
    if (fabsf(g) < 1e-3f) return 1.0f - 2.0f * u;
    const float s = (1.0f - g * g) / (1.0f - g + 2.0f * g * u);
    return fminf(1.0f, fmaxf(-1.0f, (1.0f + g * g - s * s) / (2.0f * g)));
}

/// The two lobes' anisotropies and the forward lobe's weight.
struct CloudPhase {
    float forwardG, backwardG, forwardWeight;
};

/// The phase of `layer`, its anisotropy scaled by `anisotropyScale` (Wrenninge's octaves flatten it).
URBIS_HD inline CloudPhase cloudPhase(const CloudLayer& layer, float anisotropyScale = 1.0f) {
    return {layer.forwardG * anisotropyScale, layer.backwardG * anisotropyScale, layer.forwardWeight};
}

/// The two-lobe phase function (per steradian) at the cosine of the scattering angle; also the pdf
/// (solid angle) of sampleCloudPhase.
URBIS_HD inline float cloudPhaseValue(const CloudPhase& p, float cosTheta) {
    return p.forwardWeight * henyeyGreenstein(p.forwardG, cosTheta) +
           (1.0f - p.forwardWeight) * henyeyGreenstein(p.backwardG, cosTheta);
}

/// A direction of scattered light for light travelling along the unit `dir`, distributed as the
/// phase function: `uLobe` picks the lobe, (u1, u2) the angle and the azimuth.
URBIS_HD inline Vec3f sampleCloudPhase(const CloudPhase& p, Vec3f dir, float uLobe, float u1, float u2) {
    const float g = uLobe < p.forwardWeight ? p.forwardG : p.backwardG;
    return Frame::fromZ(dir).toWorld(directionAtCosine(sampleHenyeyGreensteinCosine(g, u1), u2));
}

} // namespace urbis
