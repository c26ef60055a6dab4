// Scattering of every material kind (host+device): evaluation for light sampling, and sampling
// beside its pdf. Directions are unit and point away from the surface; n is the geometric
// normal on the side of wo.
#pragma once

#include "math/frame.h"
#include "math/fresnel.h"
#include "math/sampling.h"
#include "scene/material.h"

namespace urbis {

/// Mirror reflection of `wo` about `n`.
URBIS_HD inline Vec3f reflect(Vec3f wo, Vec3f n) { return n * (2.0f * dot(wo, n)) - wo; }

/// Whether the material scatters only into single directions: light sampling cannot reach it.
URBIS_HD inline bool isSpecular(const Material& m) {
    return m.kind == MaterialKind::Mirror || m.kind == MaterialKind::Glass || m.kind == MaterialKind::Water;
}

/// Probability that a Glossy material samples its Phong lobe rather than its diffuse part.
URBIS_HD inline float glossyLobeChance(const Material& m) {
    float d = luminance(m.albedo), s = luminance(m.specular);
    return d + s > 0.0f ? s / (d + s) : 0.0f;
}

/// f(wo, wi) * cos(wi, n) of a non-specular material, and in `pdf` the solid-angle pdf with which
/// sampleBsdf picks `wi`; both zero below the surface. One call for both, as light sampling needs
/// them, so the cosine and the mirror direction are computed once.
URBIS_HD inline Vec3f evalBsdf(const Material& m, Vec3f wo, Vec3f wi, Vec3f n, float& pdf) {
    const float cosine = dot(wi, n);
    pdf = 0.0f;
    if (cosine <= 0.0f || isSpecular(m)) return {};
    Vec3f f = m.albedo * (1.0f / kPi);
    pdf = cosineHemispherePdf(cosine);
    if (m.kind == MaterialKind::Glossy) {
        const float c = dot(wi, reflect(wo, n)), lobe = glossyLobeChance(m);
        f += m.specular * ((m.exponent + 2.0f) / (2.0f * kPi) * powf(fmaxf(0.0f, c), m.exponent));
        pdf = lobe * phongLobePdf(c, m.exponent) + (1.0f - lobe) * pdf;
    }
    return f * cosine;
}

/// f(wo, wi) * cos(wi, n) of a non-specular material; zero below the surface.
URBIS_HD inline Vec3f evalBsdfCos(const Material& m, Vec3f wo, Vec3f wi, Vec3f n) {
    float pdf;
    return evalBsdf(m, wo, wi, n, pdf);
}

/// The solid-angle pdf with which sampleBsdf picks `wi` for a non-specular material.
URBIS_HD inline float bsdfPdf(const Material& m, Vec3f wo, Vec3f wi, Vec3f n) {
    float pdf;
    evalBsdf(m, wo, wi, n, pdf);
    return pdf;
}

struct BsdfSample {
    Vec3f dir;
    Vec3f weight;          ///< f * cos / pdf, or the specular throughput
    bool specular = false;
    float pdf = 0;         ///< solid angle, of the non-specular ones (bsdfPdf): for MIS
};

/// Samples a scattered direction from three uniform numbers. Returns false when the path ends
/// (a glossy sample below the surface).
URBIS_HD inline bool sampleBsdf(const Material& m, Vec3f wo, Vec3f n, float u0, float u1, float u2, BsdfSample& s) {
    switch (m.kind) {
    case MaterialKind::Mirror:
        s = {reflect(wo, n), m.albedo, true};
        return true;
    case MaterialKind::Glass: {
        // Schlick's approximation (Schlick 1994) of the Fresnel reflectance; reflect or transmit in
        // proportion, so each branch's weight is 1 (reflection) or the tint (transmission).
        if (u0 < glassFresnel(m, dot(wo, n))) s = {reflect(wo, n), Vec3f{1, 1, 1}, true};
        else s = {-wo, m.albedo, true};
        return true;
    }
    case MaterialKind::Water: {
        // A smooth interface, air on the +y side of n (n faces wo): reflect or refract in proportion
        // to the exact Fresnel reflectance; radiance refracted into a denser medium is compressed by
        // 1 / eta^2 (pbrt-v4, 9.5.2), which the way out undoes.
        const float eta = n.y > 0.0f ? m.ior : 1.0f / m.ior;
        float cosT;
        if (u0 < fresnelDielectric(dot(wo, n), eta, cosT)) s = {reflect(wo, n), Vec3f{1, 1, 1}, true};
        else s = {refractDir(wo, n, eta, cosT), Vec3f{1, 1, 1} * (1.0f / (eta * eta)), true};
        return true;
    }
    case MaterialKind::Lambertian:
    case MaterialKind::Glossy: {
        // A glossy material picks its Phong lobe about the mirror direction or, as a Lambertian one
        // does, the cosine lobe about n: one copy of the frame and the cosine sampler for both.
        const bool phong = m.kind == MaterialKind::Glossy && u0 < glossyLobeChance(m);
        const Vec3f wi = Frame::fromZ(phong ? reflect(wo, n) : n)
                             .toWorld(phong ? samplePhongLobe(u1, u2, m.exponent) : sampleCosineHemisphere(u1, u2));
        if (m.kind == MaterialKind::Lambertian) {
            s = {wi, m.albedo, false, cosineHemispherePdf(dot(wi, n))};   // cosine sampling: f * cos / pdf is the albedo
            return true;
        }
        float pdf;
        const Vec3f fCos = evalBsdf(m, wo, wi, n, pdf);
        if (!(pdf > 0.0f)) return false;
        s = {wi, fCos / pdf, false, pdf};
        return true;
    }
    }
    return false;
}

} // namespace urbis
