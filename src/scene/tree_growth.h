// How a tree's few sizes grow into its record (host+device): the one rule that both a mapped tree
// (nature/tree_records.h, on the host) and a forest's hashed tree (geometry/forest_intersect.h, per
// ray) follow. Every operation is one of urbis.h's exact ones, so the GPU grows a forest's tree to the
// same bits as the CPU (the record decides hits).
#pragma once

#include "math/constants.h"
#include "math/hash.h"
#include "scene/tree_record.h"

#include <cstdint>

namespace urbis {

/// The trees' (bark, leaves) material pairs: a record's material is the first of its pair
/// (TreeMaterial), at firstMaterial + 2 * pair (nature/tree_records.h makes them in this order).
enum class TreeLeaves : uint32_t { Dark, Summer, Light, Needles, Autumn, Count };

/// What is known of a tree before it grows: metres; an untagged size is a default that varies.
struct TreeSizes {
    float height = 10.0f;
    float crownDiameter = 0.0f;   ///< used where crownTagged
    float circumference = 0.0f;   ///< of the trunk; 0: 1.8 % of the height as its radius
    bool heightTagged = false, crownTagged = false;
    bool conifer = false;
    bool autumn = false;          ///< a deciduous broadleaf in autumn: TreeLeaves::Autumn
};

/// How untagged trees vary and how rough their crowns are (TreeOptions' sizeVariation, roughness, lumps).
struct TreeStyle {
    float sizeVariation = 0.25f;
    float roughness = 0.18f;
    float lumps = 1.5f;
};

/// The record of a tree at `base` grown from `sizes`, its variation drawn from `rng` (untagged height
/// and crown within +-sizeVariation, the noise's seed, a summer broadleaf's shade): untagged, the
/// crown's diameter 0.6 (broadleaf) or 0.35 (conifer) of the height; the trunk's radius 1.8 % of the
/// height; the crown from 35 % (broadleaf) or 15 % (conifer) of the height.
URBIS_HD inline TreeRecord grownTreeRecord(Vec3f base, const TreeSizes& sizes, const TreeStyle& style, HashStream& rng,
                                           uint32_t object, uint32_t firstMaterial) {
    const float v = style.sizeVariation;
    const auto varied = [&](float value, bool tagged) {
        const float u = exactMulAdd(exactAdd(v, v), rng.uniform(), -v);
        return tagged ? value : exactMul(value, exactAdd(1.0f, u));
    };
    const auto clamped = [](float x, float lo, float hi) { return fminf(fmaxf(x, lo), hi); };
    TreeRecord r;
    r.base = base;
    r.height = clamped(varied(sizes.height, sizes.heightTagged), 1.0f, 150.0f);
    const float diameter = sizes.crownTagged ? sizes.crownDiameter : exactMul(r.height, sizes.conifer ? 0.35f : 0.6f);
    r.crownRadius = clamped(exactMul(0.5f, varied(diameter, sizes.crownTagged)), 0.3f, 40.0f);
    r.crownBase = exactMul(r.height, sizes.conifer ? 0.15f : 0.35f);
    // A broadleaf crown's half height must not be less than a tenth of its radius (a flat disc would
    // make the ellipsoid's scale, and so the steps, tiny).
    r.crownBase = fminf(r.crownBase, exactSub(r.height, exactMul(0.2f, r.crownRadius)));
    const float girthRadius = sizes.circumference > 0.0f ? exactDiv(sizes.circumference, exactMul(2.0f, kPi)) : exactMul(0.018f, r.height);
    r.trunkRadius = clamped(girthRadius, 0.03f, exactMul(0.5f, r.crownRadius));
    r.roughness = exactMul(style.roughness, r.crownRadius);
    r.frequency = exactDiv(style.lumps, r.crownRadius);
    r.seed = rng.next();
    r.object = object;
    r.shape = sizes.conifer ? TreeShape::Conifer : TreeShape::Broadleaf;
    const TreeLeaves leaves = sizes.conifer ? TreeLeaves::Needles : sizes.autumn ? TreeLeaves::Autumn : TreeLeaves(rng.next() % 3u);
    r.material = firstMaterial + 2u * uint32_t(leaves);
    return r;
}

} // namespace urbis
