#include "media/atmosphere_build.h"

#include "media/atmosphere_lut.h"

#include <tbb/parallel_for.h>

#include <cstring>

namespace urbis {

namespace {

ArrayView<Vec3f> viewOf(const std::vector<Vec3f>& lut) { return {lut.data(), uint32_t(lut.size())}; }

Vec3f expNegative(Vec3f x) { return {expf(-x.x), expf(-x.y), expf(-x.z)}; }

/// (1 - e^-tau) / sigma per channel: the integral of e^-(sigma s) over a step of optical depth tau.
Vec3f stepIntegral(Vec3f sigma, Vec3f stepTransmittance, float dt) {
    Vec3f out;
    for (int c = 0; c < 3; ++c)
        out[c] = sigma[c] > 1e-9f ? (1.0f - stepTransmittance[c]) / sigma[c] : dt;
    return out;
}

/// Calls texel(i, j) for every texel of a w x h table, rows in parallel: each texel is its own,
/// so the table is the same for any thread count.
template <typename Texel>
void forEachTexel(uint32_t w, uint32_t h, Texel&& texel) {
    tbb::parallel_for(uint32_t(0), h, [&](uint32_t j) {
        for (uint32_t i = 0; i < w; ++i) texel(i, j);
    });
}

/// What integrateScattering returns, per unit of solar irradiance.
struct ScatteringIntegral {
    Vec3f radiance;  ///< towards the ray's origin
    Vec3f transfer;  ///< the integral of scattering times transmittance (Hillaire's f_ms integrand)
};

/// Integrates single scattering (and multiple scattering where `multiScatteringLut` is not empty) along
/// the ray from radius `r` (km) in the planet frame whose y axis is the local zenith, along `dir`, under
/// the sun `sunDir`, to the ground or the top of the atmosphere, in `steps` steps that grow
/// quadratically from the origin (where the medium is densest for the rays that matter). `isotropic`:
/// the phase is 1 / (4 pi) (the multiple-scattering table); `ground`: the lit ground's Lambertian
/// reflection is added where the ray meets it. Hillaire 2020 § 5.1, eq. 1-3.
ScatteringIntegral integrateScattering(const Atmosphere& a, ArrayView<Vec3f> transmittance, ArrayView<Vec3f> multiScatteringLut,
                                       float r, Vec3f dir, Vec3f sunDir, uint32_t steps, bool isotropic, bool ground) {
    const bool meetsGround = rayMeetsGround(a, r, dir.y);
    const float tMax = meetsGround ? distanceToSphere(r, dir.y, a.bottomRadius, true)
                                   : distanceToSphere(r, dir.y, a.topRadius, false);
    const Vec3f origin{0, r, 0};
    const float cosTheta = dot(dir, sunDir);
    const float phaseR = isotropic ? 0.25f / kPi : rayleighPhase(cosTheta);
    const float phaseM = isotropic ? 0.25f / kPi : miePhase(a.mieG, cosTheta);
    ScatteringIntegral out;
    Vec3f throughput{1, 1, 1};
    for (uint32_t i = 0; i < steps; ++i) {
        const float s0 = float(i) / float(steps), s1 = float(i + 1) / float(steps);
        const float t0 = tMax * s0 * s0, t1 = tMax * s1 * s1, dt = t1 - t0;
        const Vec3f p = origin + dir * (0.5f * (t0 + t1));
        const float pr = length(p), muSun = dot(p, sunDir) / pr;
        const MediumSample m = sampleMedium(a, pr - a.bottomRadius);
        const Vec3f sunT = transmittanceToTop(a, transmittance, pr, muSun);
        const Vec3f psi = multiScatteringLut.size ? multiScattering(a, multiScatteringLut, pr, muSun) : Vec3f{};
        const Vec3f scattering = m.rayleighScattering + Vec3f{m.mieScattering, m.mieScattering, m.mieScattering};
        const Vec3f source = (m.rayleighScattering * phaseR + Vec3f{1, 1, 1} * (m.mieScattering * phaseM)) * sunT +
                             scattering * psi;
        const Vec3f stepT = expNegative(m.extinction * dt);
        const Vec3f integral = stepIntegral(m.extinction, stepT, dt);
        out.radiance += throughput * source * integral;
        out.transfer += throughput * scattering * integral;
        throughput *= stepT;
    }
    if (ground && meetsGround) {
        const Vec3f p = origin + dir * tMax;
        const float pr = length(p), muSun = dot(p, sunDir) / pr;
        const Vec3f sunT = transmittanceToTop(a, transmittance, pr, muSun);
        out.radiance += throughput * sunT * (fmaxf(muSun, 0.0f) / kPi) * a.groundAlbedo;
    }
    return out;
}

/// The sun's direction in the planet frame of a point whose sun has zenith cosine `muSun`: azimuth 0.
Vec3f planetSunDirection(float muSun) { return {sqrtf(fmaxf(0.0f, 1.0f - muSun * muSun)), muSun, 0.0f}; }

} // namespace

std::vector<Vec3f> buildTransmittanceLut(const Atmosphere& a) {
    // Uniform midpoint steps. The longest ray (about 1100 km, grazing the ground) takes steps of 11 km
    // where its height grows as t^2 / 2R (a scale of 120 km for the aerosols' 1.2 km); a vertical one
    // steps of 1 km against scale heights of 1.2 and 8 km: the midpoint rule's error, (step / scale)^2
    // / 24 of the optical depth, keeps the transmittance well within 0.1 %.
    constexpr uint32_t kSteps = 100;
    std::vector<Vec3f> lut(size_t(kTransmittanceLutWidth) * kTransmittanceLutHeight);
    forEachTexel(kTransmittanceLutWidth, kTransmittanceLutHeight, [&](uint32_t i, uint32_t j) {
        float r, mu;
        transmittanceLutParams(a, {float(i) / float(kTransmittanceLutWidth - 1), float(j) / float(kTransmittanceLutHeight - 1)},
                               r, mu);
        const float dt = fmaxf(0.0f, distanceToSphere(r, mu, a.topRadius, false)) / float(kSteps);
        Vec3f depth;
        for (uint32_t k = 0; k < kSteps; ++k) {
            const float t = (float(k) + 0.5f) * dt;
            const float h = sqrtf(r * r + t * t + 2.0f * r * mu * t) - a.bottomRadius;
            depth += sampleMedium(a, h).extinction * dt;
        }
        lut[size_t(j) * kTransmittanceLutWidth + i] = expNegative(depth);
    });
    return lut;
}

std::vector<Vec3f> buildMultiScatteringLut(const Atmosphere& a, const std::vector<Vec3f>& transmittance) {
    constexpr uint32_t kRings = 8, kSteps = 20;  // 8 x 8 directions, equal solid angles; the paper's 20 steps
    constexpr uint32_t n = kMultiScatteringLutSize;
    std::vector<Vec3f> lut(size_t(n) * n);
    forEachTexel(n, n, [&](uint32_t i, uint32_t j) {
        const float r = a.bottomRadius + (a.topRadius - a.bottomRadius) * float(j) / float(n - 1);
        const Vec3f sunDir = planetSunDirection(2.0f * float(i) / float(n - 1) - 1.0f);
        // L_2nd and f_ms are integrals over the sphere with the isotropic phase: means over the directions.
        Vec3f secondOrder, transfer;
        for (uint32_t u = 0; u < kRings; ++u)
            for (uint32_t v = 0; v < kRings; ++v) {
                const float cosTheta = 1.0f - 2.0f * (float(u) + 0.5f) / float(kRings);
                const float sinTheta = sqrtf(fmaxf(0.0f, 1.0f - cosTheta * cosTheta));
                const float phi = 2.0f * kPi * (float(v) + 0.5f) / float(kRings);
                const Vec3f dir{sinTheta * cosf(phi), cosTheta, sinTheta * sinf(phi)};
                const ScatteringIntegral s =
                    integrateScattering(a, viewOf(transmittance), {}, r, dir, sunDir, kSteps, true, true);
                secondOrder += s.radiance;
                transfer += s.transfer;
            }
        const float count = float(kRings * kRings), isotropic = 0.25f / kPi, sphere = 4.0f * kPi;
        secondOrder *= isotropic * sphere / count;
        transfer *= isotropic * sphere / count;
        // Psi_ms = L_2nd / (1 - f_ms): every order of scattering as a geometric series (eq. 9).
        lut[size_t(j) * n + i] = {secondOrder.x / (1.0f - transfer.x), secondOrder.y / (1.0f - transfer.y),
                                  secondOrder.z / (1.0f - transfer.z)};
    });
    return lut;
}

std::vector<Vec3f> buildSkyViewLut(const Atmosphere& a, const std::vector<Vec3f>& transmittance,
                                   const std::vector<Vec3f>& multiScattering) {
    constexpr uint32_t kSteps = 64;
    std::vector<Vec3f> lut(size_t(kSkyViewLutWidth) * kSkyViewLutHeight);
    const float r = skyViewRadius(a);
    const Vec3f sunDir = planetSunDirection(a.sunDirection.y);
    forEachTexel(kSkyViewLutWidth, kSkyViewLutHeight, [&](uint32_t i, uint32_t j) {
        float cosZenith, cosAzimuth;
        skyViewLutParams(a, {float(i) / float(kSkyViewLutWidth - 1), float(j) / float(kSkyViewLutHeight - 1)},
                         cosZenith, cosAzimuth);
        const float sinZenith = sqrtf(fmaxf(0.0f, 1.0f - cosZenith * cosZenith));
        const float sinAzimuth = sqrtf(fmaxf(0.0f, 1.0f - cosAzimuth * cosAzimuth));
        const Vec3f dir{sinZenith * cosAzimuth, cosZenith, sinZenith * sinAzimuth};
        const ScatteringIntegral s = integrateScattering(a, viewOf(transmittance), viewOf(multiScattering), r, dir,
                                                         sunDir, kSteps, false, true);
        lut[size_t(j) * kSkyViewLutWidth + i] = s.radiance * a.solarIrradiance;
    });
    return lut;
}

bool sameMedium(const Atmosphere& a, const Atmosphere& b) {
    Atmosphere sunOfB = a;
    sunOfB.sunDirection = b.sunDirection;
    sunOfB.solarIrradiance = b.solarIrradiance;
    return std::memcmp(&sunOfB, &b, sizeof b) == 0;   // floats alone: no padding
}

void buildAtmosphere(Scene& scene, bool multipleScattering, const Atmosphere* tablesBuiltFor) {
    if (scene.sky.model != SkyModel::Atmosphere) {
        scene.transmittanceLut.clear();
        scene.multiScatteringLut.clear();
        scene.skyViewLut.clear();
        return;
    }
    Atmosphere& a = scene.sky.atmosphere;
    a.sunDirection = scene.sun.direction;
    a.solarIrradiance = scene.sun.radiance * (2.0f * kPi * (1.0f - scene.sun.cosHalfAngle));
    const bool keepTables = multipleScattering && tablesBuiltFor && sameMedium(*tablesBuiltFor, a) &&
                            !scene.transmittanceLut.empty() && !scene.multiScatteringLut.empty();
    if (!keepTables) {
        scene.transmittanceLut = buildTransmittanceLut(a);
        scene.multiScatteringLut = multipleScattering
                                       ? buildMultiScatteringLut(a, scene.transmittanceLut)
                                       : std::vector<Vec3f>(size_t(kMultiScatteringLutSize) * kMultiScatteringLutSize);
    }
    scene.skyViewLut = buildSkyViewLut(a, scene.transmittanceLut, scene.multiScatteringLut);
    scene.sun.radiance *= transmittanceToTop(a, viewOf(scene.transmittanceLut), skyViewRadius(a), a.sunDirection.y);
}

} // namespace urbis
