// A path's scattering vertex and how the ray that left it was drawn (host+device): what the path
// tracer's light samples and MIS weights read (integrators/path_lights.h).
#pragma once

#include "integrators/bsdf.h"
#include "lights/light_bvh.h"

namespace urbis {

/// Offset from a surface point to clear it along its facing normal, scaled with the point's magnitude
/// so that new rays clear the surface at city coordinates (thousands of metres) in float precision.
URBIS_HD inline Vec3f rayOriginOffset(Vec3f p, Vec3f facingNormal) {
    return facingNormal * (4e-6f * maxComponent(Vec3f{fabsf(p.x), fabsf(p.y), fabsf(p.z)}) + 1e-4f);
}

/// The origin of rays that leave the surface point `p` on the side of `facingNormal`.
URBIS_HD inline Vec3f offsetRayOrigin(Vec3f p, Vec3f facingNormal) { return p + rayOriginOffset(p, facingNormal); }

/// A scattering point of the path, kept while its light samples are traced.
struct PathVertex {
    Vec3f origin;                ///< of its shadow rays, offset from the surface (offsetRayOrigin); lights are sampled from it
    Vec3f normal, wo;            ///< normal: geometric, on the side of wo
    Vec3f throughput;            ///< of the path up to this vertex
    uint32_t material = 0;
    bool bsdfStrategy = false;   ///< whether the path samples its BSDF here (not at maxDepth): MIS counts it
    bool inCloud = false;        ///< a cloud's droplet: its phase function scatters (media/cloud_scattering.h)
};

/// Where the light samples of `vertex` are drawn from, for the light sampler: also where the pick
/// probability of what its BSDF sample finds is asked.
URBIS_HD inline LightSampleContext lightContext(const PathVertex& vertex) { return {vertex.origin, vertex.normal}; }

/// How the BSDF sample that found an emitter was drawn: MIS weighs what it finds.
struct BounceInfo {
    float pdf = 0;        ///< solid angle
    bool countsInFull = true;  ///< camera rays and specular bounces: no light sample can find the same light
    /// The ray left a scattering vertex at `from` with pdf `pdf` and went on only straight through
    /// panes since: what a light kind behind panes shows (Light::kFoundThroughPanes: lit rooms) is
    /// what the vertex's light samples could reach through the pane, so MIS weighs it though
    /// countsInFull is set.
    bool windowPath = false;
    LightSampleContext from{};  ///< the vertex the BSDF sample left: where the pick probability of what it finds is asked
};

/// The BounceInfo of the ray that a BSDF sample `bsdf` of `material` sends on from `vertex`, after a
/// ray of `before`: a pane's straight transmission keeps the window path of the ray it continues.
URBIS_HD inline BounceInfo bounceAfter(const BounceInfo& before, const PathVertex& vertex, const Material& material,
                                       const BsdfSample& bsdf) {
    if (!bsdf.specular) return {bsdf.pdf, false, true, lightContext(vertex)};
    const bool throughPane = material.kind == MaterialKind::Glass && dot(bsdf.dir, vertex.normal) < 0.0f;
    return {before.pdf, true, throughPane && before.windowPath, before.from};
}

} // namespace urbis
