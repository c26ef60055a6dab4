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

/// The layers of a block's photon buffers: its facades (cylindrical) by the way they face, east
/// (+x), south (+z), west and north, so that walls met along one ray from the block's axis (a street
/// front and the side walls of the gaps behind it) keep apart; its roofs and its ground (orthographic).
enum class PhotonLayer : uint32_t { FacadeEast, FacadeSouth, FacadeWest, FacadeNorth, Roof, Ground };
inline constexpr uint32_t kPhotonFacadeLayers = 4, kPhotonLayers = 6;

/// A block of buildings and its photon buffers. The geometry is built once per scene
/// (integrators/photon_blocks.h); the allocation per render (level, texels) when the block is first
/// seen (integrators/photon_buffer_layout.h).
struct PhotonBlock {
    Vec3f lo, hi;             ///< box of its buildings, world metres
    Vec2f centre;             ///< (x, z) of the cylindrical projection's axis
    Vec2f groundLo, groundHi; ///< (x, z) rectangle of the orthographic layers: the box and the ground cells it owns
    uint32_t texelOffset = kNoTexels;  ///< first texel of its buffers; kNoTexels: no memory (not seen)
    uint32_t facadeU = 0, facadeV = 0; ///< texels around (angle) and up, per facade layer
    uint32_t topU = 0, topV = 0;       ///< texels along x and z, per orthographic layer
    uint32_t level = 0;                ///< 0-4: texel side = base texel x 2^level
    uint32_t firstPass = 0;            ///< the pass its buffers began to accumulate in

    /// Texels of one facade layer and of one orthographic layer.
    URBIS_HD uint32_t facadeTexels() const { return facadeU * facadeV; }
    URBIS_HD uint32_t topTexels() const { return topU * topV; }
    /// First texel of `layer`.
    URBIS_HD uint32_t layerOffset(PhotonLayer layer) const {
        const uint32_t k = uint32_t(layer), f = kPhotonFacadeLayers;
        return texelOffset + (k < f ? k * facadeTexels() : f * facadeTexels() + (k - f) * topTexels());
    }
    URBIS_HD uint32_t texels() const { return kPhotonFacadeLayers * facadeTexels() + 2 * topTexels(); }
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
