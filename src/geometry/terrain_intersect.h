// Ray/terrain intersection (host+device): the conservative march over the min/max hierarchy, the
// Cambridge work's dynamic-step march and a fixed-step reference, selected by TerrainRecord::march.
//
// The conservative march descends the hierarchy (TerrainRecord: level 0 holds the min and max of
// each cell's four samples, which bound the bilinear patch exactly) front to back, skipping every
// node whose box the ray misses: empty space is skipped exactly, and nothing is stepped over. In a
// cell the height along the ray is quadratic in t, so the hit is a root of a quadratic, solved in
// closed form; no refinement is needed. Every operation that decides a hit is exact (urbis.h), so
// both backends find the same distance bit for bit. The two marches are there to be measured
// (bench --terrain-accuracy) and use plain arithmetic.
#pragma once

#include "geometry/surface_hit.h"
#include "math/value_noise.h"
#include "scene/terrain_record.h"

namespace urbis {

/// The ray's interval [t0, t1] in the box x in [xa, xb], y in [ya, yb], z in [za, zb]: exact slabs,
/// widened by a relative 1e-5 so that a node's interval holds every patch root of its cells that the
/// cell test accepts. False if empty.
URBIS_HD inline bool terrainBoxInterval(const Ray& ray, const float invDir[3], float xa, float xb, float ya, float yb,
                                        float za, float zb, float& t0, float& t1) {
    const float lo[3] = {xa, ya, za}, hi[3] = {xb, yb, zb};
    float tn = -3.0e38f, tf = 3.0e38f;
    for (int a = 0; a < 3; ++a) {
        const float ta = exactMul(exactSub(lo[a], ray.origin[a]), invDir[a]);
        const float tb = exactMul(exactSub(hi[a], ray.origin[a]), invDir[a]);
        tn = fmaxf(tn, fminf(ta, tb));
        tf = fminf(tf, fmaxf(ta, tb));
    }
    constexpr float kWiden = 1e-5f;
    t0 = exactSub(tn, exactMul(fabsf(tn), kWiden));
    t1 = exactAdd(tf, exactMul(fabsf(tf), kWiden));
    return t0 <= t1 && t1 > ray.tmin && t0 < ray.tmax;
}

/// The interval of hierarchy node (l, i, j) (see terrainBoxInterval).
URBIS_HD inline bool terrainNodeInterval(const TerrainRecord& t, const float* data, const Ray& ray, const float invDir[3],
                                         uint32_t l, uint32_t i, uint32_t j, float& t0, float& t1) {
    const float* mm = data + t.levelStart[l] + 2 * (size_t(j) * t.levelWidth(l) + i);
    const uint32_t ia = i << l, ib = ((i + 1) << l) < t.cellsX() ? (i + 1) << l : t.cellsX();
    const uint32_t ja = j << l, jb = ((j + 1) << l) < t.cellsZ() ? (j + 1) << l : t.cellsZ();
    return terrainBoxInterval(ray, invDir, exactMulAdd(t.cell, float(ia), t.x0), exactMulAdd(t.cell, float(ib), t.x0),
                              mm[0], mm[1], exactMulAdd(t.cell, float(ja), t.z0), exactMulAdd(t.cell, float(jb), t.z0),
                              t0, t1);
}

/// The first t in (max(t0, tmin), min(t1, tmax)) where the ray meets cell (i, j)'s bilinear patch.
/// With t = te + s (te the entry) and (u, v) the cell's unit coordinates, y(s) - h(u(s), v(s)) =
/// A s^2 + B s + C; its roots in the stable form (Numerical Recipes 5.6). Exact: it decides hits.
URBIS_HD inline bool intersectTerrainCell(const TerrainRecord& t, const float* data, const Ray& ray, uint32_t i,
                                          uint32_t j, float t0, float t1, float& hitT) {
    const float te = fmaxf(t0, ray.tmin), tx = fminf(t1, ray.tmax);
    const float* row = data + size_t(j) * t.nx + i;
    const float h00 = row[0], h10 = row[1], h01 = row[t.nx], h11 = row[t.nx + 1];
    const float k1 = exactSub(h10, h00), k2 = exactSub(h01, h00);
    const float k4 = exactAdd(exactSub(exactSub(h00, h10), h01), h11);
    const float inv = exactDiv(1.0f, t.cell);
    const float ue = exactMul(exactSub(exactMulAdd(te, ray.dir.x, ray.origin.x), exactMulAdd(t.cell, float(i), t.x0)), inv);
    const float ve = exactMul(exactSub(exactMulAdd(te, ray.dir.z, ray.origin.z), exactMulAdd(t.cell, float(j), t.z0)), inv);
    const float ye = exactMulAdd(te, ray.dir.y, ray.origin.y);
    const float du = exactMul(ray.dir.x, inv), dv = exactMul(ray.dir.z, inv);
    const float he = exactAdd(exactAdd(exactAdd(h00, exactMul(k1, ue)), exactMul(k2, ve)), exactMul(k4, exactMul(ue, ve)));
    const float A = -exactMul(k4, exactMul(du, dv));
    const float B = exactSub(exactSub(exactSub(ray.dir.y, exactMul(k1, du)), exactMul(k2, dv)),
                             exactMul(k4, exactAdd(exactMul(ue, dv), exactMul(ve, du))));
    const float C = exactSub(ye, he);
    float r0, r1;
    if (A == 0.0f) {
        if (B == 0.0f) return false;
        r0 = r1 = exactDiv(-C, B);
    } else {
        const float disc = exactSub(exactMul(B, B), exactMul(exactMul(4.0f, A), C));
        if (disc < 0.0f) return false;
        const float q = exactMul(-0.5f, exactAdd(B, copysignf(exactSqrt(disc), B)));
        r0 = exactDiv(q, A);
        r1 = q != 0.0f ? exactDiv(C, q) : r0;
        if (r1 < r0) {
            const float r = r0;
            r0 = r1, r1 = r;
        }
    }
    const float roots[2] = {r0, r1};
    for (int k = 0; k < 2; ++k) {
        const float hit = exactAdd(te, roots[k]);
        if (hit >= te && hit <= tx && hit > ray.tmin && hit < ray.tmax) {
            hitT = hit;
            return true;
        }
    }
    return false;
}

/// The conservative march: the nearest hit of the hierarchy's patches (see the file's comment).
URBIS_HD inline bool intersectTerrainHierarchy(const TerrainRecord& t, const float* data, const Ray& ray,
                                               const float invDir[3], float& hitT) {
    struct Node {
        uint32_t level, i, j;
        float t0, t1;
    };
    // Each visit pops one node and pushes at most four: 3 per level and the root.
    Node stack[3 * kTerrainMaxLevels + 1];
    uint32_t size = 0;
    float best = ray.tmax;
    bool found = false;
    Node root{t.levels - 1, 0, 0, 0, 0};
    if (!terrainNodeInterval(t, data, ray, invDir, root.level, 0, 0, root.t0, root.t1)) return false;
    stack[size++] = root;
    while (size > 0) {
        const Node n = stack[--size];
        if (n.t0 >= best) continue;
        if (n.level == 0) {
            Ray clipped = ray;
            clipped.tmax = best;
            float th;
            if (intersectTerrainCell(t, data, clipped, n.i, n.j, n.t0, n.t1, th)) best = th, found = true;
            continue;
        }
        Node kids[4];
        uint32_t count = 0;
        const uint32_t l = n.level - 1;
        for (uint32_t c = 0; c < 4; ++c) {
            const uint32_t i = 2 * n.i + (c & 1), j = 2 * n.j + (c >> 1);
            if (i >= t.levelWidth(l) || j >= t.levelHeight(l)) continue;
            Node k{l, i, j, 0, 0};
            if (!terrainNodeInterval(t, data, ray, invDir, l, i, j, k.t0, k.t1) || k.t0 >= best) continue;
            // Insertion by entry, farthest first, so that the nearest is popped first.
            uint32_t at = count++;
            while (at > 0 && kids[at - 1].t0 < k.t0) kids[at] = kids[at - 1], --at;
            kids[at] = k;
        }
        for (uint32_t c = 0; c < count; ++c) stack[size++] = kids[c];
    }
    if (found) hitT = best;
    return found;
}

/// A march of steps step(t, y - h) from the terrain box's entry, then `bisections` halvings of the
/// last step once the ray is below the ground: the Cambridge work's scheme, and with a constant step
/// the reference. Plain arithmetic (a measured method, not the one that decides hits by default).
template <typename Step>
URBIS_HD inline bool marchTerrain(const TerrainRecord& t, const float* data, const Ray& ray, const float invDir[3],
                                  Step step, uint32_t bisections, float& hitT) {
    const Bounds3f box = primBounds(t);
    float t0, t1;
    if (!terrainBoxInterval(ray, invDir, box.lo.x, box.hi.x, box.lo.y, box.hi.y, box.lo.z, box.hi.z, t0, t1)) return false;
    const float len = sqrtf(dot(ray.dir, ray.dir));
    float prev = fmaxf(t0, ray.tmin), at = prev;
    const float end = fminf(t1, ray.tmax);
    // The last step stops at the box's exit, which the surface may touch (heights raised to its floor).
    for (uint32_t n = 0; n < (1u << 26); ++n) {
        const Vec3f p = pointAt(ray, at);
        const float dy = p.y - terrainHeight(t, data, p.x, p.z);
        if (dy <= 0.0f) {
            float lo = prev, hi = at;
            for (uint32_t b = 0; b < bisections; ++b) {
                const float mid = 0.5f * (lo + hi);
                const Vec3f q = pointAt(ray, mid);
                (q.y - terrainHeight(t, data, q.x, q.z) <= 0.0f ? hi : lo) = mid;
            }
            if (!(hi > ray.tmin && hi < ray.tmax)) return false;
            hitT = hi;
            return true;
        }
        if (at >= end) break;
        prev = at;
        at = fminf(at + fmaxf(step(at * len, dy), 1e-4f) / len, end);
    }
    return false;
}

/// The terrain's hit by its record's march.
URBIS_HD inline bool intersectTerrain(const TerrainRecord& t, const float* data, const Ray& ray, const float invDir[3],
                                      float& hitT) {
    switch (t.march) {
    case TerrainMarch::Lei:
        return marchTerrain(t, data, ray, invDir, [&](float dist, float dy) { return t.leiA + t.leiB * dist + t.leiC * dy; },
                            t.leiBisections, hitT);
    case TerrainMarch::Reference:
        return marchTerrain(t, data, ray, invDir, [&](float, float) { return t.referenceStep; }, 24, hitT);
    default:
        return intersectTerrainHierarchy(t, data, ray, invDir, hitT);
    }
}

/// The material at a terrain point (world metres) with unit normal `n`: by height, slope and a
/// noise that frays the borders between them.
URBIS_HD inline uint32_t terrainMaterialAt(const TerrainRecord& t, Vec3f p, Vec3f n) {
    const float noise = valueNoise(t.seed + 303u, {p.x * 0.043f, p.z * 0.043f}).value +
                        0.5f * valueNoise(t.seed + 304u, {p.x * 0.21f, p.z * 0.21f}).value;
    const float slope = 1.0f - n.y;
    TerrainMaterial m = TerrainMaterial::Grass;
    if (slope > t.rockSlope + 0.08f * noise) m = TerrainMaterial::Rock;
    else if (p.y > t.snowLevel + 25.0f * noise) m = TerrainMaterial::Snow;
    else if (p.y < t.sandLevel + 1.5f * noise) m = TerrainMaterial::Sand;
    return t.material + uint32_t(m);
}

template <>
struct KindIntersector<TerrainRecord> {
    /// The terrain reads its samples (SceneView::terrainData) beside its record.
    static constexpr bool kReadsScene = true;
    URBIS_HD static bool intersect(const SceneView& scene, const TerrainRecord& t, const TraceRay& tr, Ray& ray,
                                   PrimHit& hit, bool) {
        float th;
        if (!intersectTerrain(t, scene.terrainData.data, ray, tr.bvh.invDir, th)) return false;
        hit.t = th;
        ray.tmax = th;
        return true;
    }
    URBIS_HD static SurfaceHit surface(const SceneView& scene, uint32_t, const TerrainRecord& t, const PrimHit& hit,
                                       const Ray& ray) {
        const Vec3f p = pointAt(ray, hit.t);
        Vec2f g;
        terrainHeight(t, scene.terrainData.data, p.x, p.z, &g);
        const Vec3f n = normalize(Vec3f{-g.x, 1.0f, -g.y});
        return {kNoPrimKind, hit.t, p, n, {1.0f, g.x, 0.0f}, {p.x, p.z}, terrainMaterialAt(t, p, n), 0, SurfacePart::Whole};
    }
};

} // namespace urbis
