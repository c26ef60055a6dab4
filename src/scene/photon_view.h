// What per-ray code sees of a photon pass (host+device POD): the emission sphere, the reference photon
// map's hash grid and the photon buffers of the building blocks (Argudo, Andujar and Patow,
// "Interactive rendering of urban models with global illumination"). The backends fill it per pass
// (cpu/cpu_photons.cpp, gpu/gpu_photons.cu); integrators/photon_*.h read it. docs/photons.md.
#pragma once

#include "math/vec.h"

#include <cstdint>

namespace urbis {

/// A photon stored for the photon map: where it landed, where it came from, what it carries.
struct Photon {
    Vec3f position;   ///< world, metres
    Vec3f wi;         ///< unit, towards where it came from
    Vec3f power;      ///< flux, renderer units, already divided by the photons of the pass; zero: an empty slot
};

/// The hash grid of one pass's photons: photons sorted by the hash of their cell (of side 2 r),
/// bucket b holding photons [cellStart[b], cellEnd[b]).
struct PhotonGridView {
    const Photon* photons = nullptr;
    const uint32_t* cellStart = nullptr;
    const uint32_t* cellEnd = nullptr;
    uint32_t tableMask = 0;   ///< buckets - 1 (a power of two)
    float cellSize = 0;       ///< metres: twice the gather radius
    float radius = 0;         ///< metres: this pass's gather radius (progressive: shrinks by pass)
};

inline constexpr uint32_t kNoBlock = 0xffffffffu;
inline constexpr uint32_t kNoTexels = 0xffffffffu;

/// The layers of a block's photon buffers. Its facades by the way they face, east (+x), south (+z),
/// west and north, and by the half of the block they stand in: outer where they face away from the
/// block's centre (street fronts), inner where they face it (courtyards, the walls of gaps and steps),
/// so that opposite sides of a block keep apart as in the paper's cylindrical projection; each projected
/// orthographically along the way it faces onto the side of the block's box. Its roofs and its ground
/// orthographic along y.
enum class PhotonLayer : uint32_t {
    FacadeEast, FacadeSouth, FacadeWest, FacadeNorth, InnerEast, InnerSouth, InnerWest, InnerNorth, Roof, Ground
};
inline constexpr uint32_t kPhotonFacadeLayers = 8, kPhotonLayers = 10;

/// Whether the facade layer `layer` spans the block along x (walls facing south or north); else along z.
URBIS_HD inline bool facadeLayerAlongX(PhotonLayer layer) { return (uint32_t(layer) & 1u) != 0; }

/// A block of buildings and its photon buffers. The geometry is built once per scene
/// (integrators/photon_blocks.h); the allocation per render (level, texels) when the block is first
/// seen (integrators/photon_buffer_layout.h).
struct PhotonBlock {
    Vec3f lo, hi;             ///< box of its buildings, world metres
    Vec2f centre;             ///< (x, z) where the outer and the inner facade layers part
    Vec2f groundLo, groundHi; ///< (x, z) rectangle of the orthographic layers: the box and the ground cells it owns
    uint32_t texelOffset = kNoTexels;  ///< first texel of its buffers; kNoTexels: no memory (not seen)
    uint32_t facadeX = 0, facadeZ = 0, facadeV = 0; ///< texels of the facade layers along x, along z (the box's sides) and up
    uint32_t topU = 0, topV = 0;       ///< texels along x and z, per orthographic layer
    uint32_t level = 0;                ///< 0-4: texel side = base texel x 2^level
    uint32_t firstPass = 0;            ///< the pass its buffers began to accumulate in

    /// Texels of the facade layers along x and along z, and of one orthographic layer.
    URBIS_HD uint32_t facadeTexelsX() const { return facadeX * facadeV; }
    URBIS_HD uint32_t facadeTexelsZ() const { return facadeZ * facadeV; }
    URBIS_HD uint32_t topTexels() const { return topU * topV; }
    /// First texel of `layer`: the facade layers alternate along z (east, west) and along x (south, north).
    URBIS_HD uint32_t layerOffset(PhotonLayer layer) const {
        const uint32_t k = uint32_t(layer), f = kPhotonFacadeLayers, pair = facadeTexelsZ() + facadeTexelsX();
        return texelOffset + (k < f ? (k >> 1) * pair + (k & 1) * facadeTexelsZ() : (f >> 1) * pair + (k - f) * topTexels());
    }
    URBIS_HD uint32_t texels() const { return (kPhotonFacadeLayers >> 1) * (facadeTexelsZ() + facadeTexelsX()) + 2 * topTexels(); }
};

/// The photon buffers: blocks, which block each building and each ground cell belongs to, and the
/// texels, three 64-bit fixed-point sums of irradiance (R, G, B) each: integer additions are
/// associative, so the sums are the same bits for any order of the splats (any thread count, CPU or GPU).
struct PhotonBuffersView {
    const PhotonBlock* blocks = nullptr;
    uint32_t blockCount = 0;
    const uint32_t* blockOfObject = nullptr;  ///< by building object id - 1
    uint32_t objectCount = 0;
    const uint32_t* groundCells = nullptr;    ///< block of each ground cell, row-major over z then x; kNoBlock: none
    uint32_t groundW = 0, groundH = 0;
    Vec2f groundLo;                           ///< (x, z) of the grid's corner
    float groundCell = 0;                     ///< metres
    unsigned long long* texels = nullptr;     ///< 3 per texel
    float fixedScale = 0;                     ///< a texel's integer = irradiance x fixedScale
};

/// The integrators that draw on photons (IntegratorKind::PhotonMap, PhotonBuffers) see this.
struct PhotonsView {
    Vec3f centre;              ///< of the sphere photons of infinite lights (sun, moon, sky) are aimed at
    float radius = 0;          ///< metres
    float skyPmf = 0;          ///< probability that a photon leaves the sky when the sky is not in the light list
    uint32_t pass = 0;         ///< index of this pass (the photons' random numbers, the buffers' pass count)
    PhotonGridView grid;
    PhotonBuffersView buffers;
};

} // namespace urbis
