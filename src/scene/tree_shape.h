// A tree's signed distance function (host+device), in tree coordinates (TreeRecord): a tapered
// trunk, four branches (broadleaf) and a crown, an ellipsoid or a tiered cone, whose distance is
// displaced by value noise. The sphere tracer (geometry/tree_intersect.h), primBounds and the
// triangle twin (nature/tree_mesher.h) all read this one shape, so the two representations cannot
// drift apart.
//
// The function is not an exact distance but a lower bound of one times a known Lipschitz constant
// (`lipschitz`): every part is 1-Lipschitz (the ellipsoid's scaled-sphere bound, the cones scaled by
// the cosine of their steepest slope), and the noise adds roughness * frequency * kTreeNoiseGradient.
// A step of f / lipschitz therefore never passes the surface (Hart, "Sphere tracing", The Visual
// Computer 12, 1996, section 3). What decides hits, so every multiply-add here is one of urbis.h's
// exact operations: nvcc would otherwise fuse them and put the device's surface a rounding away.
#pragma once

#include "math/hash.h"
#include "scene/surface_part.h"
#include "scene/tree_record.h"

namespace urbis {

/// A bound of |grad| of treeNoise: each partial derivative is the smoothstep's slope (at most 1.5)
/// times a difference of two values in [-1, 1], so |grad| <= 3 sqrt(3) = 5.196.
inline constexpr float kTreeNoiseGradient = 5.2f;
/// Branches of a broadleaf tree.
inline constexpr int kTreeBranches = 4;

URBIS_HD inline Vec3f exactSub3(Vec3f a, Vec3f b) { return {exactSub(a.x, b.x), exactSub(a.y, b.y), exactSub(a.z, b.z)}; }
URBIS_HD inline float exactLength(Vec3f a) { return exactSqrt(exactDot(a, a)); }
URBIS_HD inline float exactHypot(float x, float z) { return exactSqrt(exactAdd(exactMul(x, x), exactMul(z, z))); }

/// What the distance function needs of a record, worked out once per ray and tree.
struct TreeShapeParams {
    bool conifer = false;
    float trunkTop = 0, trunkRadius = 0, trunkSlope = 0, trunkScale = 1;   ///< radius r0 - slope y up to trunkTop; 1/sqrt(1 + slope^2)
    float crownBase = 0, crownTop = 0, crownRadius = 0;
    Vec3f crownCentre, crownInvRadii;  ///< broadleaf: the ellipsoid
    float crownMinRadius = 0;
    float coneInvHeight = 0, coneScale = 1, tiers = 0;  ///< conifer: 1 / crown height, 1/sqrt(1 + k^2) of the steepest slope k, tiers
    Vec3f branchFrom[kTreeBranches], branchAxis[kTreeBranches];
    float branchInvLength2[kTreeBranches] = {}, branchRadius = 0;
    float roughness = 0, frequency = 0;
    Vec3f noiseOffset;
    uint32_t seed = 0;
    float lipschitz = 1;
};

/// Eight horizontal directions, 45 degrees apart: the branches' (a table, so no sine decides a hit).
URBIS_TABLE float kTreeBranchDirs[8][2] = {{1.0f, 0.0f},  {0.70710678f, 0.70710678f},  {0.0f, 1.0f},  {-0.70710678f, 0.70710678f},
                                           {-1.0f, 0.0f}, {-0.70710678f, -0.70710678f}, {0.0f, -1.0f}, {0.70710678f, -0.70710678f}};

URBIS_HD inline TreeShapeParams treeShapeOf(const TreeRecord& t) {
    TreeShapeParams s;
    s.conifer = t.shape == TreeShape::Conifer;
    s.crownBase = t.crownBase;
    s.crownTop = t.height;
    s.crownRadius = t.crownRadius;
    const float crownHeight = exactSub(t.height, t.crownBase);
    s.trunkRadius = t.trunkRadius;
    // A conifer's trunk runs to 85 % of its height inside the cone and narrows by 70 %; a
    // broadleaf's stops inside the crown, at 45 % of it, at half its foot's radius.
    s.trunkTop = s.conifer ? exactMul(0.85f, t.height) : exactMulAdd(0.45f, crownHeight, t.crownBase);
    s.trunkSlope = exactDiv(exactMul(s.conifer ? 0.7f : 0.5f, t.trunkRadius), s.trunkTop);
    s.trunkScale = exactDiv(1.0f, exactSqrt(exactMulAdd(s.trunkSlope, s.trunkSlope, 1.0f)));
    const float halfHeight = exactMul(0.5f, crownHeight);
    s.crownCentre = {0.0f, exactAdd(t.crownBase, halfHeight), 0.0f};
    s.crownInvRadii = {exactDiv(1.0f, t.crownRadius), exactDiv(1.0f, halfHeight), exactDiv(1.0f, t.crownRadius)};
    s.crownMinRadius = fminf(t.crownRadius, halfHeight);
    // The cone's radius R (1 - s) (0.78 + 0.22 tri(tiers s)), s up the crown: its slope in y is at
    // most R / H (1 + 0.44 tiers); a tier every 2.5 m, 3 to 8 of them.
    s.coneInvHeight = exactDiv(1.0f, crownHeight);
    s.tiers = fminf(8.0f, fmaxf(3.0f, floorf(exactMul(crownHeight, 0.4f))));
    const float k = exactMul(exactMul(t.crownRadius, s.coneInvHeight), exactMulAdd(0.44f, s.tiers, 1.0f));
    s.coneScale = exactDiv(1.0f, exactSqrt(exactMulAdd(k, k, 1.0f)));
    // Branches from the trunk below the crown up and out into it, the first direction by the seed.
    s.branchRadius = exactMul(0.45f, t.trunkRadius);
    for (int b = 0; b < kTreeBranches; ++b) {
        const uint32_t dir = (t.seed + 3u * uint32_t(b)) & 7u;
        const float rise = exactMul(crownHeight, exactMulAdd(0.05f, float(b), 0.35f)), reach = exactMul(t.crownRadius, 0.7f);
        s.branchFrom[b] = {0.0f, exactMul(t.crownBase, exactMulAdd(0.08f, float(b), 0.72f)), 0.0f};
        s.branchAxis[b] = {exactMul(reach, kTreeBranchDirs[dir][0]), exactAdd(exactSub(t.crownBase, s.branchFrom[b].y), rise),
                           exactMul(reach, kTreeBranchDirs[dir][1])};
        s.branchInvLength2[b] = exactDiv(1.0f, exactDot(s.branchAxis[b], s.branchAxis[b]));
    }
    s.roughness = t.roughness;
    s.frequency = t.frequency;
    s.seed = t.seed;
    s.noiseOffset = {hashToUnit(hash2(t.seed, 1u)) * 64.0f, hashToUnit(hash2(t.seed, 2u)) * 64.0f,
                     hashToUnit(hash2(t.seed, 3u)) * 64.0f};
    s.lipschitz = exactAdd(1.0f, exactMul(exactMul(t.roughness, t.frequency), kTreeNoiseGradient));
    return s;
}

/// A value in [-1, 1] hashed from a lattice point (one PCG round of the coordinates' spatial hash,
/// Teschner et al. 2003).
URBIS_HD inline float treeLatticeValue(uint32_t seed, int x, int y, int z) {
    const uint32_t h = pcgHash(seed ^ uint32_t(x) * 73856093u ^ uint32_t(y) * 19349663u ^ uint32_t(z) * 83492791u);
    return exactSub(exactMul(hashToUnit(h), 2.0f), 1.0f);
}

URBIS_HD inline float exactLerp(float a, float b, float t) { return exactAdd(a, exactMul(exactSub(b, a), t)); }
URBIS_HD inline float exactSmoothstep(float f) { return exactMul(exactMul(f, f), exactSub(3.0f, exactMul(2.0f, f))); }

/// Value noise in [-1, 1] of lattice spacing 1 at `p`: trilinear between hashed lattice values with
/// smoothstep weights (|grad| <= kTreeNoiseGradient).
URBIS_HD inline float treeNoise(Vec3f p, uint32_t seed) {
    const float fx = floorf(p.x), fy = floorf(p.y), fz = floorf(p.z);
    const int ix = int(fx), iy = int(fy), iz = int(fz);
    const float sx = exactSmoothstep(exactSub(p.x, fx)), sy = exactSmoothstep(exactSub(p.y, fy)),
                sz = exactSmoothstep(exactSub(p.z, fz));
    float plane[2];
    for (int dz = 0; dz < 2; ++dz) {
        float row[2];
        for (int dy = 0; dy < 2; ++dy)
            row[dy] = exactLerp(treeLatticeValue(seed, ix, iy + dy, iz + dz), treeLatticeValue(seed, ix + 1, iy + dy, iz + dz), sx);
        plane[dz] = exactLerp(row[0], row[1], sy);
    }
    return exactLerp(plane[0], plane[1], sz);
}

/// Distance bound to the wood: the trunk (a cone cut at 0 and trunkTop) and the branches (capsules).
URBIS_HD inline float treeWoodDistance(const TreeShapeParams& s, Vec3f q) {
    const float radius = exactSub(s.trunkRadius, exactMul(s.trunkSlope, fminf(fmaxf(q.y, 0.0f), s.trunkTop)));
    float d = fmaxf(exactMul(exactSub(exactHypot(q.x, q.z), radius), s.trunkScale), fmaxf(-q.y, exactSub(q.y, s.trunkTop)));
    if (s.conifer) return d;
    for (int b = 0; b < kTreeBranches; ++b) {
        const Vec3f pa = exactSub3(q, s.branchFrom[b]), ba = s.branchAxis[b];
        const float h = fminf(fmaxf(exactMul(exactDot(pa, ba), s.branchInvLength2[b]), 0.0f), 1.0f);
        const Vec3f off{exactSub(pa.x, exactMul(ba.x, h)), exactSub(pa.y, exactMul(ba.y, h)), exactSub(pa.z, exactMul(ba.z, h))};
        d = fminf(d, exactSub(exactLength(off), s.branchRadius));
    }
    return d;
}

/// Distance bound to the crown before its displacement.
URBIS_HD inline float treeCrownShapeDistance(const TreeShapeParams& s, Vec3f q) {
    if (!s.conifer) {
        const Vec3f c = exactSub3(q, s.crownCentre);
        const Vec3f u{exactMul(c.x, s.crownInvRadii.x), exactMul(c.y, s.crownInvRadii.y), exactMul(c.z, s.crownInvRadii.z)};
        return exactMul(exactSub(exactLength(u), 1.0f), s.crownMinRadius);
    }
    const float up = fminf(fmaxf(exactMul(exactSub(q.y, s.crownBase), s.coneInvHeight), 0.0f), 1.0f);
    const float x = exactMul(s.tiers, up), wave = fabsf(exactSub(exactMul(2.0f, exactSub(x, floorf(x))), 1.0f));
    const float radius = exactMul(exactMul(s.crownRadius, exactSub(1.0f, up)), exactMulAdd(0.22f, wave, 0.78f));
    const float side = exactMul(exactSub(exactHypot(q.x, q.z), radius), s.coneScale);
    return fmaxf(side, fmaxf(exactSub(s.crownBase, q.y), exactSub(q.y, s.crownTop)));
}

/// Distance bound to the displaced crown.
URBIS_HD inline float treeCrownDistance(const TreeShapeParams& s, Vec3f q) {
    const Vec3f p{exactMulAdd(q.x, s.frequency, s.noiseOffset.x), exactMulAdd(q.y, s.frequency, s.noiseOffset.y),
                  exactMulAdd(q.z, s.frequency, s.noiseOffset.z)};
    return exactMulAdd(s.roughness, treeNoise(p, s.seed), treeCrownShapeDistance(s, q));
}

/// The tree's distance bound at `q` (tree coordinates): f / s.lipschitz is at most the distance to its surface.
URBIS_HD inline float treeDistance(const TreeShapeParams& s, Vec3f q) {
    return fminf(treeWoodDistance(s, q), treeCrownDistance(s, q));
}

/// Tree-coordinate bounds of every point where treeDistance can be zero or less: the crown's shape
/// grown by the noise's amplitude over its scale (crownMinRadius, coneScale), the trunk and branches.
/// Exact: the sphere tracer clips rays to it.
URBIS_HD inline Bounds3f treeLocalBounds(const TreeShapeParams& s) {
    const float grow = exactDiv(s.roughness, s.conifer ? s.coneScale : s.crownMinRadius);
    const float rx = s.conifer ? exactAdd(s.crownRadius, grow) : exactMulAdd(s.crownRadius, grow, s.crownRadius);
    const float halfHeight = exactSub(s.crownTop, s.crownCentre.y);
    const float top = s.conifer ? exactAdd(s.crownTop, s.roughness)
                                : exactAdd(s.crownCentre.y, exactMulAdd(halfHeight, grow, halfHeight));
    const float reach = fmaxf(rx, fmaxf(s.trunkRadius, exactMulAdd(0.7f, s.crownRadius, s.branchRadius)));
    return {{-reach, 0.0f, -reach}, {reach, fmaxf(top, s.trunkTop), reach}};
}

/// The part a hit at `q` belongs to: the crown's leaves or the wood.
URBIS_HD inline SurfacePart treePartAt(const TreeShapeParams& s, Vec3f q) {
    return treeCrownDistance(s, q) < treeWoodDistance(s, q) ? SurfacePart::TreeCrown : SurfacePart::TreeTrunk;
}

} // namespace urbis
