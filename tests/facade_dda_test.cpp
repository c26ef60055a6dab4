// The wall intersector's grid walk (2D DDA) against brute force over every part of every cell, on
// millions of random rays: from anywhere, nearly parallel to the wall, grazing its slab, starting
// inside a room or on a balcony.
#include "facade_test_walls.h"
#include "geometry/wall_intersect.h"

#include <gtest/gtest.h>

#include <random>

using namespace urbis;
using namespace urbis::test;

namespace {

/// A diagonal wall of 5 slots x 6 floors with balconies and shop windows, or a curtain wall.
WallRecord testWall(WallStyle style) {
    WallRecord w;
    giveTestFacade(style, w);
    w.origin = {1203.5f, 4.0f, -2210.25f};
    w.axisU = normalize(Vec3f{0.8f, 0, -0.6f});
    w.normal = Vec3f{-w.axisU.z, 0, w.axisU.x};
    w.width = 17.0f;
    w.height = 20.1f;
    w.slots = 5;
    w.floors = 6;
    w.slotWidth = 16.0f / 5.0f;
    w.floorHeight = 19.2f / 6.0f;
    w.windowWidth = 1.5f;
    w.windowHeight = 1.5f;
    w.object = 7;
    w.wallIndex = 3;
    w.cellSeed = 12345;
    return w;
}

/// Tests every part of `parts`; returns whether any was hit (closest in `hit`, tmax shrunk).
bool intersectWallParts(const CellParts& parts, const WallRay& r, float& tmax, WallHit& hit) {
    bool found = false;
    for (int i = 0; i < parts.count; ++i) found |= intersectWallPart(parts.parts[i], r, tmax, hit);
    return found;
}

/// Closest hit over the margins and every part of every cell. By default the parts are the
/// intersector's (both sides of the glass: the room as a box, the frame and the glass plane as quads
/// with the opening); with `twinParts` they are the triangle twin's quads and boxes.
bool bruteForce(const WallRecord& wall, const Ray& ray, WallHit& hit, bool twinParts = false) {
    const WallRay r(wall, ray);
    float tmax = ray.tmax;
    CellParts margins;
    marginParts(wall, margins);
    bool found = intersectWallParts(margins, r, tmax, hit);
    for (uint32_t j = 0; j < wall.floors; ++j)
        for (uint32_t i = 0; i < wall.slots; ++i)
            for (CellSide side : {CellSide::Front, CellSide::Back, CellSide::Both}) {
                if ((side == CellSide::Both) != twinParts) continue;
                CellParts cell;
                cellParts(wall, j, i, side, cell);
                found |= intersectWallParts(cell, r, tmax, hit);
            }
    return found;
}

Vec3f randomDirection(std::mt19937& rng) {
    std::normal_distribution<float> n;
    return normalize(Vec3f{n(rng), n(rng), n(rng)});
}

/// Whether wall point (u, v, w) lies inside the wall's solid body (behind the wall plane, but neither
/// in a room nor in a window's recess) or in a curtain wall's mullions: no ray of a path can start there.
bool insideSolid(const WallRecord& w, Vec3f p) {
    const float front = w.style == WallStyle::Curtain ? kMullionDepth : 0.0f;
    if (p.x < 0 || p.x > w.width || p.y < 0 || p.y > w.height || p.z <= -w.depthBack || p.z >= front) return false;
    const float fu = (p.x - w.gridU) / w.slotWidth, fv = (p.y - w.gridV) / w.floorHeight;
    if (fu < 0 || fv < 0 || fu >= w.slots || fv >= w.floors) return p.z < 0;
    const CellLayout c = cellLayout(w, uint32_t(fv), uint32_t(fu));
    const float inset = 0.05f;
    if (p.z < -w.reveal) return !(p.x > c.u0 + inset && p.x < c.u1 - inset && p.y > c.v0 + inset && p.y < c.v1 - inset);
    return !(p.x > c.ou0 && p.x < c.ou1 && p.y > c.ov0 && p.y < c.ov1);
}

enum class RayKind { Anywhere, NearlyParallel, Grazing, InsideRoom, OnBalcony };

Ray randomRay(const WallRecord& w, RayKind kind, std::mt19937& rng) {
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    auto wallPoint = [&](float u, float v, float d) { return w.worldFromWall(u, v, d); };
    Ray ray;
    switch (kind) {
    case RayKind::Anywhere:
        ray.origin = wallPoint(-5 + 27 * unit(rng), -3 + 26 * unit(rng), -5 + 15 * unit(rng));
        ray.dir = randomDirection(rng);
        break;
    case RayKind::NearlyParallel: {
        ray.origin = wallPoint(-5 + 27 * unit(rng), -3 + 26 * unit(rng), -4 + 6 * unit(rng));
        const float a = unit(rng) * 6.2831853f, tilt = (unit(rng) - 0.5f) * 2e-3f;
        ray.dir = normalize(w.axisU * cosf(a) + Vec3f{0, sinf(a), 0} + w.normal * tilt);
        break;
    }
    case RayKind::Grazing: {
        // Starts just outside the slab's front or back face, heading in at a shallow angle.
        const bool front = unit(rng) < 0.5f;
        const float d = front ? w.depthFront + 0.01f * unit(rng) : -w.depthBack - 0.01f * unit(rng);
        ray.origin = wallPoint(-2 + 21 * unit(rng), -2 + 24 * unit(rng), d);
        const float a = unit(rng) * 6.2831853f, tilt = 0.002f + 0.05f * unit(rng);
        ray.dir = normalize(w.axisU * cosf(a) + Vec3f{0, sinf(a), 0} + w.normal * (front ? -tilt : tilt));
        break;
    }
    case RayKind::InsideRoom: {
        const float slot = float(int(unit(rng) * w.slots)), floor = float(int(unit(rng) * w.floors));
        ray.origin = wallPoint(w.gridU + w.slotWidth * (slot + 0.1f + 0.8f * unit(rng)),
                               w.gridV + w.floorHeight * (floor + 0.1f + 0.8f * unit(rng)),
                               -w.reveal - 0.05f - (w.depthBack - w.reveal - 0.1f) * unit(rng));
        ray.dir = randomDirection(rng);
        break;
    }
    case RayKind::OnBalcony: {
        // Above the slab of a cell's bottom, in front of the wall (on a balcony where there is one).
        const float slot = float(int(unit(rng) * w.slots)), floor = float(1 + int(unit(rng) * (w.floors - 1)));
        ray.origin = wallPoint(w.gridU + w.slotWidth * (slot + 0.2f + 0.6f * unit(rng)),
                               w.gridV + w.floorHeight * floor + 0.16f + 0.8f * unit(rng), 0.05f + 1.0f * unit(rng));
        ray.dir = randomDirection(rng);
        break;
    }
    }
    return ray;
}

/// Whether the ray reaches its hit at t from inside the wall's solid body (round the wall's end or
/// under its bottom, behind the wall plane): such a hit has no defined answer, and in a scene the
/// building's other walls or the ground stop the ray first.
bool reachedThroughSolid(const WallRecord& wall, const Ray& ray, float t) {
    const WallRay r(wall, ray);
    return insideSolid(wall, r.o + r.d * fmaxf(0.0f, t - 1e-3f));
}

/// Whether two answers differ: hit vs miss, distances apart by more than a millimetre, or another
/// material or part.
bool differ(bool a, const WallHit& x, bool b, const WallHit& y) {
    return a != b || (a && (fabsf(x.t - y.t) > 1e-3f || x.material != y.material || x.part != y.part));
}

/// Random rays of `kind` that do not start inside the wall's solid body.
Ray randomOpenRay(const WallRecord& wall, RayKind kind, std::mt19937& rng) {
    Ray ray = randomRay(wall, kind, rng);
    while (insideSolid(wall, WallRay(wall, ray).o)) ray = randomRay(wall, kind, rng);
    return ray;
}

/// Rays on which the intersector and the brute force differ (the closest and the any-hit query).
size_t disagreements(const WallRecord& wall, RayKind kind, size_t rays, size_t& hits) {
    std::mt19937 rng(uint32_t(kind) * 7919u + uint32_t(wall.style));
    size_t bad = 0;
    for (size_t k = 0; k < rays; ++k) {
        const Ray ray = randomOpenRay(wall, kind, rng);
        WallHit fast, slow;
        const bool a = intersectWall<false>(wall, ray, fast), b = bruteForce(wall, ray, slow);
        WallHit any;
        const bool c = intersectWall<true>(wall, ray, any);
        hits += b;
        if ((a && reachedThroughSolid(wall, ray, fast.t)) || (b && reachedThroughSolid(wall, ray, slow.t))) continue;
        if (differ(a, fast, b, slow) || c != b) ++bad;
    }
    return bad;
}

/// Rays on which the intersector's parts and the twin's quads (both by brute force) differ.
size_t twinPartDisagreements(const WallRecord& wall, RayKind kind, size_t rays) {
    std::mt19937 rng(uint32_t(kind) * 104729u + uint32_t(wall.style));
    size_t bad = 0;
    for (size_t k = 0; k < rays; ++k) {
        const Ray ray = randomOpenRay(wall, kind, rng);
        WallHit own, twin;
        const bool a = bruteForce(wall, ray, own), b = bruteForce(wall, ray, twin, true);
        if ((a && reachedThroughSolid(wall, ray, own.t)) || (b && reachedThroughSolid(wall, ray, twin.t))) continue;
        bad += differ(a, own, b, twin);
    }
    return bad;
}

constexpr size_t kRaysPerKind = 400000;

} // namespace

class FacadeDda : public ::testing::TestWithParam<std::tuple<WallStyle, RayKind>> {};

TEST_P(FacadeDda, MatchesBruteForceOverEveryCell) {
    const auto [style, kind] = GetParam();
    const WallRecord wall = testWall(style);
    size_t hits = 0;
    const size_t bad = disagreements(wall, kind, kRaysPerKind, hits);
    // Rounding at shared part edges (kWallPartPadding) may differ in a handful of rays (0.01 %):
    // rays within 0.2 mm of an edge, where padded parts overlap.
    EXPECT_LE(bad, kRaysPerKind / 10000) << "of " << kRaysPerKind << " rays, " << hits << " hits";
    EXPECT_GT(hits, kRaysPerKind / 20) << "the rays must actually meet the wall";
}

class FacadeParts : public ::testing::TestWithParam<std::tuple<WallStyle, RayKind>> {};

TEST_P(FacadeParts, IntersectorsPartsMatchTheTwinsQuads) {
    const auto [style, kind] = GetParam();
    const size_t rays = kRaysPerKind / 4, bad = twinPartDisagreements(testWall(style), kind, rays);
    // The twin's padded quads reach kWallPartPadding beyond a room's edges and a window's recess,
    // where the intersector's boxes do not: rays grazing in from behind the rooms meet a side quad's
    // padding before the back face (0.2 % of them, measured), and rays nearly parallel to the wall
    // that skim the wall or glass plane within that padding meet a jamb's (0.012 %, measured); the
    // boxes meet them where the unpadded surfaces do. Elsewhere both agree but for rays within the
    // padding of a shared edge (0.01 %).
    const size_t allowed = kind == RayKind::Grazing ? rays * 3 / 1000 : (kind == RayKind::NearlyParallel ? rays * 2 / 10000 : rays / 10000);
    EXPECT_LE(bad, allowed) << "of " << rays << " rays";
}

INSTANTIATE_TEST_SUITE_P(AllRayKinds, FacadeParts,
                         ::testing::Combine(::testing::Values(WallStyle::Punched, WallStyle::Curtain),
                                            ::testing::Values(RayKind::Anywhere, RayKind::NearlyParallel,
                                                              RayKind::Grazing, RayKind::InsideRoom,
                                                              RayKind::OnBalcony)));

INSTANTIATE_TEST_SUITE_P(AllRayKinds, FacadeDda,
                         ::testing::Combine(::testing::Values(WallStyle::Punched, WallStyle::Curtain),
                                            ::testing::Values(RayKind::Anywhere, RayKind::NearlyParallel,
                                                              RayKind::Grazing, RayKind::InsideRoom,
                                                              RayKind::OnBalcony)));
