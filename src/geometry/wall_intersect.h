// Ray/procedural-wall intersection (host+device): the ray is taken into wall coordinates, the wall
// plane's margins are one plane test, and the floor x slot grid is walked cell by cell along the
// ray (as a 2D DDA, J. Amanatides and A. Woo, "A Fast Voxel Traversal Algorithm for Ray Tracing",
// Eurographics 1987, each step taken from the bounds of the cell it leaves), testing only the
// parts of the cells the ray passes through. What decides the hit uses urbis.h's exact operations,
// so that a ray hits the same part at the same distance on both backends.
#pragma once

#include "accel/bvh_traverse.h"
#include "geometry/wall_parapet.h"
#include "geometry/wall_parts.h"
#include "math/ray.h"

namespace urbis {

/// A hit on a wall: distance, the wall-space axis of the surface normal, what was hit.
struct WallHit {
    float t = 0;
    uint32_t axis = 0;       ///< 0: along the wall, 1: up, 2: the wall's normal
    uint32_t material = 0;
    SurfacePart part = SurfacePart::Facade;
};

/// Metres by which part extents are widened when tested, so that rounding never lets a ray slip
/// between two parts that share an edge (the parts overlap by this much instead).
inline constexpr float kWallPartPadding = 2e-4f;

/// A ray in wall coordinates (the same t as in world space).
struct WallRay {
    Vec3f o, d, invD;
    float tmin;

    /// `invDirY`: BvhRay::safeInverse(ray.dir.y), the y axis being the same in both (the traversal's
    /// BvhRay has it already).
    URBIS_HD WallRay(const WallRecord& wall, const Ray& ray, float invDirY) : tmin(ray.tmin) {
        const Vec3f rel = ray.origin - wall.origin;
        o = {exactDot(rel, wall.axisU), rel.y, exactDot(rel, wall.normal)};
        d = {exactDot(ray.dir, wall.axisU), ray.dir.y, exactDot(ray.dir, wall.normal)};
        invD = {BvhRay::safeInverse(d.x), invDirY, BvhRay::safeInverse(d.z)};
    }
    URBIS_HD WallRay(const WallRecord& wall, const Ray& ray) : WallRay(wall, ray, BvhRay::safeInverse(ray.dir.y)) {}

    /// o + t d on axis a (exact).
    URBIS_HD float at(int a, float t) const { return exactMulAdd(t, d[a], o[a]); }

    /// Whether the ray meets the plane w = w0 at tmin < t < tmax: then t and the point's u, v there.
    URBIS_HD bool crossesW(float w0, float tmax, float& t, float& u, float& v) const {
        if (d.z == 0.0f) return false;
        t = (w0 - o.z) * invD.z;
        if (!(t > tmin && t < tmax)) return false;
        u = at(0, t);
        v = at(1, t);
        return true;
    }
};

/// The part of a ray's segment (t0, t1) inside slabs of wall coordinates, clipped one axis at a time.
struct SegmentClip {
    float t0, t1;

    /// Keeps the segment where lo <= o + t d <= hi (inv = 1 / d); empty (t0 > t1) if none.
    URBIS_HD void clip(float o, float d, float inv, float lo, float hi) {
        if (d == 0.0f) {
            if (o < lo || o > hi) t0 = 3.0e38f;
            return;
        }
        const float ta = (lo - o) * inv, tb = (hi - o) * inv;
        const float near = ta < tb ? ta : tb, far = ta < tb ? tb : ta;
        t0 = near > t0 ? near : t0;
        t1 = far < t1 ? far : t1;
    }
    URBIS_HD bool empty() const { return t0 > t1; }

    /// Keeps the segment inside the box lo..hi on the first `axes` axes (u, v, w) of wall
    /// coordinates: a loop rather than a copy per axis, for the GPU's instruction cache.
    URBIS_HD void clipToBox(const WallRay& r, Vec3f lo, Vec3f hi, int axes) {
        URBIS_NO_UNROLL
        for (int a = 0; a < axes; ++a) clip(r.o[a], r.d[a], r.invD[a], lo[a], hi[a]);
    }
};

/// The tile's extent in u and v (WallRecord::tileU0 and the others), worked out once per wall test.
struct TileRect {
    float u0, u1, v0, v1;
    URBIS_HD explicit TileRect(const WallRecord& w) : u0(w.tileU0()), u1(w.tileU1()), v0(w.tileV0()), v1(w.tileV1()) {}
};

/// The world-space normal of a wall-space axis.
URBIS_HD inline Vec3f wallAxisNormal(const WallRecord& wall, uint32_t axis) {
    return axis == 0 ? wall.axisU : (axis == 1 ? Vec3f{0, 1, 0} : wall.normal);
}

/// The panel in part p's opening at height y (wall v): glass, or below p.panelSplit a curtain
/// cell's spandrel (its material is to the glass's as FacadeMaterial::Spandrel is to Glass). The
/// twin tests the spandrel's padded quad before the glass's, so the spandrel wins within e of the split.
URBIS_HD inline void openingPanel(const WallPart& p, float y, SurfacePart& part, uint32_t& material) {
    const bool spandrel = y < p.panelSplit + kWallPartPadding;
    part = spandrel ? SurfacePart::Spandrel : SurfacePart::Glass;
    material = p.openingMaterial + (spandrel ? uint32_t(FacadeMaterial::Spandrel) - uint32_t(FacadeMaterial::Glass) : 0u);
}

/// Tests one part with tmin < t < tmax; on a hit shrinks tmax and fills `hit`. A box is solid:
/// a ray from inside hits its exit face; a recess (PartOpening::Recess) is hollow and open at its
/// front: a ray hits the face it leaves through, or nothing if that is the front. A quad is tested
/// as a flat box (lo[axis] == hi[axis]), widened by kWallPartPadding within its plane: one slab test
/// for every part, with no indexing by the part's axis, keeps the GPU's hot code small.
URBIS_HD inline bool intersectWallPart(const WallPart& p, const WallRay& r, float& tmax, WallHit& hit) {
    constexpr float e = kWallPartPadding;
    float tNear = -3.0e38f, tFar = 3.0e38f;
    uint32_t nearAxis = 0, farAxis = 0;
    for (int a = 0; a < 3; ++a) {
        const float pad = p.axis != kWallPartBox && p.axis != a ? e : 0.0f;
        const float t0 = (p.lo[a] - pad - r.o[a]) * r.invD[a], t1 = (p.hi[a] + pad - r.o[a]) * r.invD[a];
        const float lo = t0 < t1 ? t0 : t1, hi = t0 < t1 ? t1 : t0;
        if (lo > tNear) { tNear = lo; nearAxis = uint32_t(a); }
        if (hi < tFar) { tFar = hi; farAxis = uint32_t(a); }
    }
    if (tNear > tFar) return false;
    const bool exits = !(tNear > r.tmin) || p.opening == PartOpening::Recess;
    const float t = exits ? tFar : tNear;
    if (!(t > r.tmin && t < tmax)) return false;
    const uint32_t axis = p.axis != kWallPartBox ? p.axis : (exits ? farAxis : nearAxis);
    if (p.opening == PartOpening::Recess && axis == 2 && r.d.z > 0.0f) return false;
    SurfacePart part = p.part;
    uint32_t material = p.material;
    if (axis == 2 && p.opening != PartOpening::None) {
        // As the twin's padded quads: its glass wins where it overlaps the quads around it (it is
        // tested first), and its frame overlaps the jambs. So the panel reaches e beyond the
        // opening, and a hole stops e short of it.
        const float x = r.at(0, t), y = r.at(1, t);
        const float g = p.opening == PartOpening::Hole ? -e : e;
        if (x >= p.openingLo.x - g && x <= p.openingHi.x + g && y >= p.openingLo.y - g && y <= p.openingHi.y + g) {
            if (p.opening == PartOpening::Hole) return false;
            openingPanel(p, y, part, material);
        }
    }
    tmax = t;
    hit = {t, axis, material, part};
    return true;
}

/// The margins around the grid: the plane w = 0 where it lies in the wall (in the record's tile:
/// see WallRecord::slot0) but not inside the grid.
URBIS_HD inline bool intersectWallMargins(const WallRecord& wall, const TileRect& tile, const WallRay& r, float& tmax,
                                          WallHit& hit) {
    constexpr float e = kWallPartPadding;
    float t, u, v;
    if (!r.crossesW(0.0f, tmax, t, u, v)) return false;
    if (u < tile.u0 - e || u > tile.u1 + e || v < tile.v0 - e || v > tile.v1 + e) return false;
    const bool inGrid = u > wall.gridU + e && u < wall.gridU1() - e && v > wall.gridV + e && v < wall.gridV1() - e;
    if (inGrid) return false;
    tmax = t;
    hit = {t, 2u, wall.wallMaterial, SurfacePart::Facade};
    return true;
}

/// The parapet's top and inner face (wall_parapet.h). A tile has it only where it reaches the
/// wall's top, over its own u range (open at the wall's ends, where the mitres reach beyond them).
/// Both faces lie in the slab -thickness <= w <= 0: most rays that reach a wall stay below the
/// parapet's deck there, and are turned away before the faces are tested.
URBIS_HD inline bool intersectWallParapet(const WallRecord& wall, const TileRect& tile, const WallRay& r, float& tmax,
                                          WallHit& hit) {
    constexpr float e = kWallPartPadding;
    if (!(wall.parapetHeight > 0.0f) || wall.tileFloorEnd() < int(wall.floors)) return false;
    SegmentClip slab{r.tmin, tmax};
    slab.clip(r.o.z, r.d.z, r.invD.z, -wall.parapetThickness - e, e);
    if (slab.empty() || fmaxf(r.at(1, slab.t0), r.at(1, slab.t1)) < wall.height - wall.parapetHeight - e)
        return false;
    const float uLo = wall.slot0 == 0 ? -3.0e38f : tile.u0;
    const float uHi = wall.tileSlotEnd() >= int(wall.slots) ? 3.0e38f : tile.u1;
    bool found = false;
    if (r.d.y != 0.0f) {
        const float t = (wall.height - r.o.y) * r.invD.y;
        const float u = r.at(0, t), w = r.at(2, t);
        float start, end;
        parapetSpanAt(wall, w, start, end);
        if (t > r.tmin && t < tmax && w >= -wall.parapetThickness - e && w <= e && u >= fmaxf(uLo, start) - e &&
            u <= fminf(uHi, end) + e) {
            tmax = t;
            hit = {t, 1u, wall.wallMaterial, SurfacePart::Facade};
            found = true;
        }
    }
    // The inner face (the twin's quad) tested as a point on its plane: a second copy of
    // intersectWallPart would cost the GPU's instruction cache more.
    float t, u, v;
    if (!r.crossesW(-wall.parapetThickness, tmax, t, u, v)) return found;
    const WallPart inner = parapetInnerFace(wall);
    if (u >= fmaxf(uLo, inner.lo.x) - e && u <= fminf(uHi, inner.hi.x) + e && v >= inner.lo.y - e && v <= inner.hi.y + e) {
        tmax = t;
        hit = {t, inner.axis, inner.material, inner.part};
        return true;
    }
    return found;
}

/// The closest (AnyHit = false) or any (AnyHit = true) hit of `ray` on `wall` (on its tile: see
/// WallRecord::slot0) with ray.tmin < t < ray.tmax. A ray that enters the tile's column in front of
/// the glass plane (w > -reveal) can reach only the parts in front of it, one that enters behind it
/// only the rooms' side (CellSide; the parts lie in the column and the glass plane closes it): the
/// slab walked is then w in [-reveal, depthFront] or [-depthBack, -reveal]. Visits only the cells
/// that the ray's segment inside that slab passes through, nearest first, and stops at the first
/// cell with a hit: every part of a cell lies in the cell's column, so nothing later is closer.
/// A tile walks the same cells of the same grid as its whole wall, minus those outside it, so the
/// closest hit over a wall's tiles is the whole wall's. `anyHit` is a run-time flag (see
/// traceScene); the template below fixes it at compile time. `invDirY` as for WallRay.
URBIS_HD inline bool intersectWall(const WallRecord& wall, const Ray& ray, WallHit& hit, bool anyHit, float invDirY) {
    const WallRay r(wall, ray, invDirY);
    // The margins, the parapet and the cells' column each turn away the rays that miss them: a slab
    // test of the tile's whole box first turned away few (5-9 % of the rays that reach a wall in a
    // generated city) for its cost.
    const TileRect tile(wall);
    float tmax = ray.tmax;
    bool found = intersectWallMargins(wall, tile, r, tmax, hit);
    if (found && anyHit) return true;
    found |= intersectWallParapet(wall, tile, r, tmax, hit);
    if (found && anyHit) return true;
    const int slot0 = wall.slot0, slotEnd = wall.tileSlotEnd(), floor0 = wall.floor0, floorEnd = wall.tileFloorEnd();
    if (slot0 >= slotEnd || floor0 >= floorEnd) return found;
    // Clip the ray to the tile's column; where it enters the column decides the side of the glass
    // it can reach (every cell part lies in the column), then clip to that side's slab.
    constexpr float e = kWallPartPadding;
    const float lo[2] = {wall.slotU(slot0) - e, wall.floorV(floor0) - e};
    const float hi[2] = {wall.slotU(slotEnd) + e, wall.floorV(floorEnd) + e};
    SegmentClip s{r.tmin, tmax};
    s.clipToBox(r, {lo[0], lo[1], 0.0f}, {hi[0], hi[1], 0.0f}, 2);
    if (s.empty()) return found;
    const CellSide side = r.o.z + s.t0 * r.d.z > -wall.reveal ? CellSide::Front : CellSide::Back;
    const bool front = side == CellSide::Front;
    s.clip(r.o.z, r.d.z, r.invD.z, (front ? -wall.reveal : -wall.depthBack) - e,
           (front ? wall.depthFront : -wall.reveal) + e);
    if (s.empty()) return found;
    // The cell of the entry point; from each cell the walk goes on through the side of the cell (its
    // bounds from cellLayout) that the ray leaves by first: a ray meets few cells of a wall (1.1 on
    // average in a generated city), so the walk keeps no increments between them.
    const float pu = r.at(0, s.t0), pv = r.at(1, s.t0);
    int i = int(floorf(exactDiv(pu - wall.gridU, wall.slotWidth))), j = int(floorf(exactDiv(pv - wall.gridV, wall.floorHeight)));
    i = i < slot0 ? slot0 : (i >= slotEnd ? slotEnd - 1 : i);
    j = j < floor0 ? floor0 : (j >= floorEnd ? floorEnd - 1 : j);
    for (;;) {
        // One part loop for every cell, two parts on either side of the glass (a balcony adds four
        // in front): closed forms let a warp's lanes take different paths and cost the GPU more.
        const CellLayout c = cellLayout(wall, uint32_t(j), uint32_t(i));
        const CellCoords coords = cellCoords(wall, c);
        const int parts = cellPartCount(wall, c, side);
        bool cellHit = false;
        URBIS_NO_UNROLL
        for (int k = 0; k < parts && !(cellHit && anyHit); ++k)
            cellHit |= intersectWallPart(cellPart(wall, c, coords, side, k), r, tmax, hit);
        if (cellHit) return true;
        const float tu = r.d.x == 0.0f ? 3.0e38f : ((r.d.x > 0.0f ? c.u1 : c.u0) - r.o.x) * r.invD.x;
        const float tv = r.d.y == 0.0f ? 3.0e38f : ((r.d.y > 0.0f ? c.v1 : c.v0) - r.o.y) * r.invD.y;
        const bool acrossU = tu < tv;
        const float tNext = acrossU ? tu : tv;
        if (tNext > s.t1 || tNext > tmax) break;
        if (acrossU) i += r.d.x > 0.0f ? 1 : -1;
        else j += r.d.y > 0.0f ? 1 : -1;
        if (i < slot0 || i >= slotEnd || j < floor0 || j >= floorEnd) break;
    }
    return found;
}

template <bool AnyHit>
URBIS_HD inline bool intersectWall(const WallRecord& wall, const Ray& ray, WallHit& hit) {
    return intersectWall(wall, ray, hit, AnyHit, BvhRay::safeInverse(ray.dir.y));
}

} // namespace urbis
