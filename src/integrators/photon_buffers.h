// Photon buffers (host+device; Argudo, Andujar and Patow, "Interactive rendering of urban models with
// global illumination"): photons splatted into persistent 2D buffers per block of buildings, its
// facades by the way they face and the half of the block they stand in, projected onto the sides of its
// box (the paper's cylindrical projection, whose Jacobian vanishes on a wall through the block's axis,
// made a box), its roofs and its ground orthographically, looked up in O(1) at the camera pass's first
// diffuse hit. A texel holds irradiance (the photons' flux over the surface area it covers), splatted
// bilinearly so that the buffer is anti-aliased, in 64-bit fixed point so that the sums do not depend
// on the splats' order. docs/photons.md § Photon buffers.
#pragma once

#include "geometry/surface_hit.h"
#include "scene/scene_view.h"

namespace urbis {

/// Adds `value` to `*target` atomically: integer sums are the same bits in any order, so the splats
/// of any thread count, CPU or GPU, sum alike.
URBIS_HD inline void atomicAddU64(unsigned long long* target, unsigned long long value) {
#if URBIS_GPU_CODE
    atomicAdd(target, value);
#else
    __atomic_fetch_add(target, value, __ATOMIC_RELAXED);
#endif
}

/// Where a surface point lies in its block's buffers: the layer and continuous texel coordinates
/// (x in [0, w), y in [0, h); texel (i, j) covers [i, i + 1) x [j, j + 1)), and the surface area one
/// texel covers there (m^2).
struct BufferPoint {
    uint32_t block = kNoBlock;
    PhotonLayer layer = PhotonLayer::Ground;
    uint32_t w = 0, h = 0;
    float x = 0, y = 0;
    float texelArea = 0;
};

/// The block of a surface point of `object` (building object id, 0 for the ground and the streets) at
/// `p`: its building's, or the ground cell's. kNoBlock where none owns it.
URBIS_HD inline uint32_t photonBlockOf(const PhotonBuffersView& b, Vec3f p, uint32_t object) {
    if (object > 0) return object - 1 < b.objectCount ? b.blockOfObject[object - 1] : kNoBlock;
    const float cx = (p.x - b.groundLo.x) / b.groundCell, cz = (p.z - b.groundLo.y) / b.groundCell;
    if (!(cx >= 0.0f && cz >= 0.0f && cx < float(b.groundW) && cz < float(b.groundH))) return kNoBlock;
    return b.groundCells[uint32_t(cz) * b.groundW + uint32_t(cx)];
}

/// The projection of point `p` with unit normal `n` onto `block`'s layer `layer` (no memory needed).
URBIS_HD inline BufferPoint projectOntoBlock(const PhotonBlock& block, PhotonLayer layer, Vec3f p, Vec3f n) {
    BufferPoint out;
    out.layer = layer;
    if (layer == PhotonLayer::Roof || layer == PhotonLayer::Ground) {
        // Orthographic along y: a texel covers its (x, z) rectangle, more on a slope.
        const float sx = (block.groundHi.x - block.groundLo.x) / float(block.topU);
        const float sz = (block.groundHi.y - block.groundLo.y) / float(block.topV);
        out.w = block.topU;
        out.h = block.topV;
        out.x = (p.x - block.groundLo.x) / sx;
        out.y = (p.z - block.groundLo.y) / sz;
        out.texelArea = sx * sz / fmaxf(fabsf(n.y), 0.2f);
        return out;
    }
    // Orthographic along the way the facade faces onto the side of the box: a texel covers its
    // rectangle of the side over the cosine between the facade and the side, at least 0.61 (the
    // facing is the larger horizontal component of a normal at most 60 degrees from horizontal; the
    // clamp at 0.5 only guards that bound).
    const bool alongX = facadeLayerAlongX(layer);
    const float lo = alongX ? block.lo.x : block.lo.z, extent = fmaxf(alongX ? block.hi.x - lo : block.hi.z - lo, 1e-3f);
    const float height = fmaxf(block.hi.y - block.lo.y, 1e-3f);
    out.w = alongX ? block.facadeX : block.facadeZ;
    out.h = block.facadeV;
    out.x = ((alongX ? p.x : p.z) - lo) / extent * float(out.w);
    out.y = (p.y - block.lo.y) / height * float(out.h);
    const float facing = fabsf(alongX ? n.z : n.x);
    out.texelArea = extent * height / (float(out.w) * float(out.h) * fmaxf(facing, 0.5f));
    return out;
}

/// Distance (metres) within which a facade at the block's centre counts as outer whichever way it
/// faces: a party wall through the centre lands on one layer, not on either by rounding.
inline constexpr float kPhotonCentreSlack = 0.05f;

/// The layer of a surface point `p` of `object` with unit normal `n` in `block`: roofs and the ground
/// orthographic (normals up), other building surfaces by the way they face and whether they face away
/// from the block's centre (outer) or towards it (inner).
URBIS_HD inline PhotonLayer photonLayerOf(const PhotonBlock& block, Vec3f p, Vec3f n, uint32_t object) {
    if (object == 0) return PhotonLayer::Ground;
    if (n.y > 0.5f) return PhotonLayer::Roof;
    const bool alongZ = fabsf(n.x) >= fabsf(n.z);
    const float facing = alongZ ? n.x : n.z, offset = alongZ ? p.x - block.centre.x : p.z - block.centre.y;
    const uint32_t side = alongZ ? (facing >= 0.0f ? 0u : 2u) : (facing >= 0.0f ? 1u : 3u);
    const bool outer = (facing >= 0.0f ? offset : -offset) > -kPhotonCentreSlack;
    return PhotonLayer(side + (outer ? 0u : 4u));
}

/// Where the surface point (`p`, unit normal `n`, `object`) lies in the buffers. False where no block
/// owns it or its block has no memory (not seen).
URBIS_HD inline bool bufferPointOf(const PhotonBuffersView& b, Vec3f p, Vec3f n, uint32_t object, BufferPoint& out) {
    const uint32_t id = photonBlockOf(b, p, object);
    if (id == kNoBlock || b.blocks[id].texelOffset == kNoTexels) return false;
    const PhotonBlock& block = b.blocks[id];
    out = projectOntoBlock(block, photonLayerOf(block, p, n, object), p, n);
    out.block = id;
    return true;
}

/// The four texels of the bilinear footprint of `bp` (layer-relative indices) and their weights,
/// which sum to one, clamped at the layer's edges.
URBIS_HD inline void bilinearTexels(const BufferPoint& bp, uint32_t index[4], float weight[4]) {
    const float fx = bp.x - 0.5f, fy = bp.y - 0.5f;
    const float x0 = floorf(fx), y0 = floorf(fy), wx = fx - x0, wy = fy - y0;
    const int w = int(bp.w), h = int(bp.h);
    int xs[2] = {int(x0), int(x0) + 1}, ys[2] = {int(y0), int(y0) + 1};
    for (int k = 0; k < 2; ++k) {
        xs[k] = xs[k] < 0 ? 0 : (xs[k] >= w ? w - 1 : xs[k]);
        ys[k] = ys[k] < 0 ? 0 : (ys[k] >= h ? h - 1 : ys[k]);
    }
    for (int k = 0; k < 4; ++k) {
        index[k] = uint32_t(ys[k >> 1]) * bp.w + uint32_t(xs[k & 1]);
        weight[k] = ((k & 1) ? wx : 1.0f - wx) * ((k >> 1) ? wy : 1.0f - wy);
    }
}

/// Whether the buffers hold light for the surface of `hit`: not the rooms behind windows, which the
/// facade projection would put on the texels of the facade in front of them.
URBIS_HD inline bool bufferedSurface(const SurfaceHit& hit) { return hit.part != SurfacePart::Room; }

/// A sink of tracePhoton that splats into the photon buffers: the photon's flux over the area a
/// texel covers where it landed, spread over four texels bilinearly. Ground-owned surfaces that do
/// not face up (lamp posts, bridge sides) have no layer of their own and take no photons.
struct PhotonSplatSink {
    PhotonBuffersView buffers;
    URBIS_HD void operator()(const SurfaceHit& hit, Vec3f, Vec3f power, uint32_t) const {
        if ((hit.object == 0 && hit.normal.y <= 0.5f) || !bufferedSurface(hit)) return;
        BufferPoint bp;
        if (!bufferPointOf(buffers, hit.position, hit.normal, hit.object, bp)) return;
        const Vec3f e = power * (buffers.fixedScale / bp.texelArea);
        const uint32_t base = buffers.blocks[bp.block].layerOffset(bp.layer);
        uint32_t index[4];
        float weight[4];
        bilinearTexels(bp, index, weight);
        for (int k = 0; k < 4; ++k) {
            if (!(weight[k] > 0.0f)) continue;
            unsigned long long* texel = buffers.texels + 3 * size_t(base + index[k]);
            const float v[3] = {e.x * weight[k], e.y * weight[k], e.z * weight[k]};
            for (int c = 0; c < 3; ++c) atomicAddU64(texel + c, (unsigned long long)(fminf(v[c], 1.8e19f) + 0.5f));
        }
    }
};

/// Irradiance from the photons at the surface point (`p`, unit normal `n`, `object`) averaged over the
/// passes its block has accumulated up to `pass`: one bilinear look-up, O(1). Zero where no block owns it.
URBIS_HD inline Vec3f bufferIrradiance(const PhotonBuffersView& b, Vec3f p, Vec3f n, uint32_t object, uint32_t pass) {
    BufferPoint bp;
    if (!bufferPointOf(b, p, n, object, bp)) return {};
    const PhotonBlock& block = b.blocks[bp.block];
    const uint32_t base = block.layerOffset(bp.layer);
    uint32_t index[4];
    float weight[4];
    bilinearTexels(bp, index, weight);
    Vec3f sum;
    for (int k = 0; k < 4; ++k) {
        const unsigned long long* texel = b.texels + 3 * size_t(base + index[k]);
        sum += Vec3f{float(texel[0]), float(texel[1]), float(texel[2])} * weight[k];
    }
    return sum / (b.fixedScale * float(pass + 1 - block.firstPass));
}

} // namespace urbis
