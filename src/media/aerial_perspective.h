// Aerial perspective (host+device): what the atmosphere does to light along one path segment between
// surfaces, so that far buildings fade into haze. Hillaire 2020 (§ 5.4) stores it in a camera-frustum
// volume; urbis evaluates it per segment instead, from the same transmittance and multiple-scattering
// tables, because a path tracer's segments start anywhere (bounces, not only the camera) and city
// segments are at most a few km long and a few hundred metres high: over one, the exponential media
// integrate in closed form along the segment, while the sun's transmittance and the multiple-scattering
// radiance (which change over kilometres of height) are taken at its middle. The segment's points
// are all taken as sunlit: buildings cast no shadows into the haze (Hillaire's shadow map term).
#pragma once

#include "media/atmosphere_lut.h"
#include "math/ray.h"
#include "scene/scene_view.h"

namespace urbis {

/// (1 - exp(-x)) / x, and its limit 1 at x = 0.
URBIS_HD inline float expIntegralRatio(float x) { return fabsf(x) < 1e-4f ? 1.0f - 0.5f * x : (1.0f - expf(-x)) / x; }

/// Column density (km) of a layer of scale height `scaleHeight` km along `length` km from height `h0`
/// km, climbing `dy` km per km: the integral of exp(-h / scaleHeight) along the segment.
URBIS_HD inline float layerColumn(float h0, float dy, float length, float scaleHeight) {
    return expf(-h0 / scaleHeight) * length * expIntegralRatio(length * dy / scaleHeight);
}

/// What a segment of the atmosphere does to the radiance arriving through it.
struct SegmentMedium {
    Vec3f transmittance{1, 1, 1};   ///< of the segment
    Vec3f inScattered;              ///< radiance it scatters towards its start (single and multiple)
};

/// The segment from world point `origin` (metres) along the unit direction `dir` over `distance`
/// metres. Ozone lies above 10 km and adds nothing at city heights.
URBIS_HD inline SegmentMedium atmosphereSegment(const Atmosphere& a, ArrayView<Vec3f> transmittanceLut,
                                                ArrayView<Vec3f> multiScatteringLut, Vec3f origin, Vec3f dir,
                                                float distance) {
    const float length = distance * 1e-3f, h0 = fmaxf(0.0f, a.altitude + origin.y * 1e-3f);
    const float rayleigh = layerColumn(h0, dir.y, length, a.rayleighScaleHeight);
    const float mie = layerColumn(h0, dir.y, length, a.mieScaleHeight);
    const Vec3f rayleighColumn = a.rayleighScattering * rayleigh;
    const float mieColumn = a.mieScattering * mie, mieExtinction = (a.mieScattering + a.mieAbsorption) * mie;
    const Vec3f opticalDepth = rayleighColumn + Vec3f{mieExtinction, mieExtinction, mieExtinction};
    SegmentMedium m;
    m.transmittance = {expf(-opticalDepth.x), expf(-opticalDepth.y), expf(-opticalDepth.z)};
    // The source (per unit of solar irradiance) at the segment's middle height, times the column of
    // scatterers, spread along the segment as its extinction weighs it: sum of column * (1 - T) / tau.
    const float r = a.bottomRadius + fmaxf(0.0f, h0 + 0.5f * length * dir.y), muSun = a.sunDirection.y;
    const Vec3f sunTransmittance = transmittanceToTop(a, transmittanceLut, r, muSun);
    const Vec3f psi = multiScattering(a, multiScatteringLut, r, muSun);
    const float cosTheta = dot(dir, a.sunDirection);
    const Vec3f single = (rayleighColumn * rayleighPhase(cosTheta) + Vec3f{1, 1, 1} * (mieColumn * miePhase(a.mieG, cosTheta))) *
                         sunTransmittance;
    const Vec3f multiple = (rayleighColumn + Vec3f{mieColumn, mieColumn, mieColumn}) * psi;
    // (1 - T) / tau from the transmittance already at hand (its limit 1 where tau is tiny).
    Vec3f spread;
    for (int c = 0; c < 3; ++c)
        spread[c] = opticalDepth[c] > 1e-4f ? (1.0f - m.transmittance[c]) / opticalDepth[c] : 1.0f - 0.5f * opticalDepth[c];
    m.inScattered = (single + multiple) * spread * a.solarIrradiance;
    return m;
}

/// Applies the scene's aerial perspective to the path segment `ray` (world; its direction of any
/// length) up to its parameter `t`: the radiance gains the segment's in-scattered light times
/// `throughput`, then the throughput takes the segment's transmittance. Nothing where the sky has no
/// medium (the analytic sky, or aerial perspective turned off).
URBIS_HD inline void applyAerialPerspective(const SceneView& scene, const Ray& ray, float t, Vec3f& throughput,
                                            Vec3f& radiance) {
    if (!hasAerialPerspective(scene.sky)) return;
    const float len = length(ray.dir);
    const SegmentMedium m = atmosphereSegment(scene.sky.atmosphere, scene.transmittanceLut, scene.multiScatteringLut,
                                              ray.origin, ray.dir / len, t * len);
    radiance += throughput * m.inScattered;
    throughput *= m.transmittance;
}

} // namespace urbis
