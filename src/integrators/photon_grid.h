// The reference photon map (host+device): photons in a hash grid of cells of side 2 r (the GPU's
// equivalent of Jensen's kd-tree, as in Hachisuka and Jensen's GPU SPPM), gathered within the radius r
// of a shading point by Epanechnikov's kernel; the radius shrinks pass by pass (Knaus and Zwicker 2011,
// "Progressive photon mapping: a probabilistic approach": r_{i+1}^2 = r_i^2 (i + alpha) / (i + 1)),
// so that the average of the passes converges. Build: cpu/cpu_photons.cpp, gpu/gpu_photons.cu.
#pragma once

#include "geometry/surface_hit.h"
#include "integrators/bsdf.h"
#include "math/rng.h"
#include "scene/scene_view.h"

namespace urbis {

/// Integer cell of `p` in a grid of cells of side `cellSize`.
URBIS_HD inline void photonCell(Vec3f p, float cellSize, int& x, int& y, int& z) {
    x = int(floorf(p.x / cellSize));
    y = int(floorf(p.y / cellSize));
    z = int(floorf(p.z / cellSize));
}

/// Bucket of cell (x, y, z) in a table of mask + 1 buckets.
URBIS_HD inline uint32_t photonBucket(int x, int y, int z, uint32_t mask) {
    return hash4(uint32_t(x), uint32_t(y), uint32_t(z), 0x9e3779b9u) & mask;
}

/// Gather radius of pass `pass` (from 0) that starts at `radius0`: r_i^2 = r_0^2 prod_{k=1..i} (k - 1 + alpha) / k.
URBIS_HD inline float photonRadiusAt(float radius0, float alpha, uint32_t pass) {
    float r2 = radius0 * radius0;
    for (uint32_t k = 1; k <= pass; ++k) r2 *= (float(k) - 1.0f + alpha) / float(k);
    return sqrtf(r2);
}

/// A sink of tracePhoton that stores into photon `index`'s slots (settings.maxDepth of them).
struct PhotonSlotSink {
    Photon* slots;
    URBIS_HD void operator()(const SurfaceHit& hit, Vec3f wi, Vec3f power, uint32_t store) const {
        slots[store] = Photon{hit.position, wi, power};
    }
};

/// Reflected radiance towards `wo` at a non-specular hit of `material` from the photons within the
/// grid's radius that arrived on the side of `normal`: sum of f(wo, wi) Phi k(d), with Epanechnikov's
/// kernel k(d) = 2 (1 - d^2 / r^2) / (pi r^2) over the tangent disk.
URBIS_HD inline Vec3f gatherPhotons(const PhotonGridView& grid, const Material& material, Vec3f p, Vec3f normal, Vec3f wo) {
    const float r = grid.radius, r2 = r * r;
    int x0, y0, z0;
    photonCell(p - Vec3f{r, r, r}, grid.cellSize, x0, y0, z0);
    Vec3f sum;
    URBIS_NO_UNROLL
    for (int c = 0; c < 8; ++c) {
        const uint32_t bucket = photonBucket(x0 + (c & 1), y0 + ((c >> 1) & 1), z0 + (c >> 2), grid.tableMask);
        // Two cells of the eight may share a bucket: each bucket counts once.
        bool seen = false;
        for (int e = 0; e < c; ++e)
            seen |= photonBucket(x0 + (e & 1), y0 + ((e >> 1) & 1), z0 + (e >> 2), grid.tableMask) == bucket;
        if (seen) continue;
        for (uint32_t i = grid.cellStart[bucket]; i < grid.cellEnd[bucket]; ++i) {
            const Photon& photon = grid.photons[i];
            const Vec3f d = photon.position - p;
            const float d2 = dot(d, d), cosine = dot(photon.wi, normal);
            // The tangent disk: photons off the plane by more than a fifth of r belong to other surfaces.
            if (d2 >= r2 || !(cosine > 0.0f) || fabsf(dot(d, normal)) > 0.2f * r) continue;
            float pdf;
            const Vec3f fCos = evalBsdf(material, wo, photon.wi, normal, pdf);
            sum += photon.power * fCos * ((1.0f - d2 / r2) / cosine);
        }
    }
    return sum * (2.0f / (kPi * r2));
}

} // namespace urbis
