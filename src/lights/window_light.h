// Lit windows (host+device): how each lit room looks (colour temperature, intensity, a curtain, the
// thesis's per-window noise), and a wall record (a tile) as one aggregate light of its lit
// windows. Everything comes from hashes of (wall seed, floor, slot): nothing per window is stored.
// A light sample picks a lit cell of the tile (uniform tries, the first lit one; the wall's count
// of lit cells, made at build, gives the exact pdf) and a uniform point of its glass; the window's glass plane is the emitter, its radiance the room's behind it
// through the pane (docs/lights.md § Lit windows).
#pragma once

#include "geometry/surface_hit.h"
#include "geometry/wall_parts.h"
#include "lights/light_build.h"
#include "lights/light_sample.h"
#include "math/constants.h"
#include "math/rng.h"
#include "math/sampling.h"
#include "scene/light_bounds.h"
#include "scene/material.h"
#include "scene/scene_view.h"

#include <vector>

namespace urbis {

/// Linear Rec.709 colours of blackbodies at 2700 K and 4000 K, luminance 1 (blackbodyRgb of
/// scene/lamp_emission.h; a test holds them to it): a room's colour lies between them.
URBIS_TABLE Vec3f kWindowWarm{1.9144f, 0.8099f, 0.1908f};
URBIS_TABLE Vec3f kWindowCool{1.4060f, 0.9265f, 0.5326f};
/// What a drawn curtain lets through, and the noise's cell (metres).
inline constexpr float kCurtainTransmission = 0.3f, kWindowNoiseScale = 0.7f;
/// Salt of the hash of a window's look, apart from cellRandom's choices of its geometry.
inline constexpr uint32_t kWindowLookSalt = 0x9e3779b9u;

/// The colour (luminance 1) of a room of `coolness` (WindowLook::coolness).
URBIS_HD inline Vec3f windowColour(float coolness) { return kWindowWarm + (kWindowCool - kWindowWarm) * coolness; }

/// The look of one lit room, from its hash.
struct WindowLook {
    float coolness;        ///< 0 at 2700 K to 1 at 4000 K
    Vec3f colour;          ///< luminance 1: the blackbody of `coolness`, between kWindowWarm and kWindowCool
    float intensity;       ///< 0.5 to 1.5 times the lit room's emission
    float curtainShare;    ///< of the opening's width a curtain covers (0: none), from curtainFromLeft's side
    bool curtainFromLeft;
    Vec3f curtainTint;     ///< luminance about 1
    uint32_t noiseKey;
};

/// The look of the room of cell (floor, slot) of `wall` (whether it is lit or not).
URBIS_HD inline WindowLook windowLook(const WallRecord& wall, uint32_t floor, uint32_t slot) {
    HashStream rng{hash3(wall.cellSeed ^ kWindowLookSalt, floor, slot)};
    WindowLook w;
    w.coolness = rng.uniform();
    w.colour = windowColour(w.coolness);
    w.intensity = 0.5f + rng.uniform();
    // Two rooms in five have a curtain partly drawn, over a fifth to four fifths of the window.
    const bool curtain = rng.uniform() < 0.4f;
    w.curtainShare = curtain ? 0.2f + 0.6f * rng.uniform() : 0.0f;
    w.curtainFromLeft = rng.uniform() < 0.5f;
    const float warmth = rng.uniform();
    w.curtainTint = Vec3f{1.25f, 0.95f, 0.7f} + (Vec3f{0.85f, 1.0f, 1.3f} - Vec3f{1.25f, 0.95f, 0.7f}) * warmth;
    w.noiseKey = rng.next();
    return w;
}

/// Smooth value noise in [0, 1] at (x, y) (units of its lattice): hashed lattice values blended by
/// a smoothstep, mean 1/2 (the thesis's per-window Perlin noise, as a cheaper value noise).
URBIS_HD inline float windowNoise(uint32_t key, float x, float y) {
    const float fx = floorf(x), fy = floorf(y);
    const int ix = int(fx), iy = int(fy);
    const float tx = x - fx, ty = y - fy;
    const float sx = tx * tx * (3.0f - 2.0f * tx), sy = ty * ty * (3.0f - 2.0f * ty);
    const auto at = [&](int dx, int dy) { return hashToUnit(hash3(key, uint32_t(ix + dx), uint32_t(iy + dy))); };
    const float bottom = at(0, 0) + (at(1, 0) - at(0, 0)) * sx, top = at(0, 1) + (at(1, 1) - at(0, 1)) * sx;
    return bottom + (top - bottom) * sy;
}

/// The part of a cell's opening that emits (wall coordinates, metres): the glass, above a curtain
/// wall's spandrel.
struct WindowRect {
    float u0, u1, v0, v1;
    URBIS_HD float area() const { return (u1 - u0) * (v1 - v0); }
};

URBIS_HD inline WindowRect windowRect(const WallRecord& wall, const CellLayout& c) {
    const float split = wall.style == WallStyle::Curtain ? c.v0 + wall.sillHeight : c.v0;
    return {c.ou0, c.ou1, fmaxf(c.ov0, split), c.ov1};
}

/// Whether the cell's room is lit.
URBIS_HD inline bool cellLit(const WallRecord& wall, const CellLayout& c) {
    return c.roomMaterial == wall.facadeMaterials + uint32_t(FacadeMaterial::RoomLit);
}

/// Radiance of a lit room seen through the window's glass plane at (u, v) (wall coordinates), before
/// the pane: `room` (the lit room's emission, its luminance the scale) times the look's colour and
/// intensity, a curtain's share dimmed and tinted, and the noise (0.6 to 1.4, mean 1).
URBIS_HD inline Vec3f windowRadiance(const WindowLook& w, const WindowRect& r, Vec3f room, float u, float v) {
    Vec3f L = w.colour * (luminance(room) * w.intensity);
    const float across = w.curtainFromLeft ? u - r.u0 : r.u1 - u;
    if (across < w.curtainShare * (r.u1 - r.u0)) L = L * w.curtainTint * kCurtainTransmission;
    return L * (0.6f + 0.8f * windowNoise(w.noiseKey, u * (1.0f / kWindowNoiseScale), v * (1.0f / kWindowNoiseScale)));
}

/// A lit window's mean luminance over its glass in units of the lit room's: its intensity, a curtain's
/// share dimmed (the noise's mean is 1).
URBIS_HD inline float windowMeanIntensity(const WindowLook& w) {
    return w.intensity * (1.0f - w.curtainShare + w.curtainShare * kCurtainTransmission * luminance(w.curtainTint));
}

/// Expected flux of a lit window through its glass plane (before the pane), renderer units: pi
/// times its area times its mean luminance.
URBIS_HD inline float windowPower(const WindowLook& w, const WindowRect& r, Vec3f room) {
    return kPi * r.area() * luminance(room) * windowMeanIntensity(w);
}

/// Cells of a wall record's tile.
URBIS_HD inline uint32_t tileCellCount(const WallRecord& wall) {
    return uint32_t(wall.tileSlotEnd() - int(wall.slot0)) * uint32_t(wall.tileFloorEnd() - int(wall.floor0));
}

/// What a pane lets through at `cosine` with its normal: its tint times one minus its reflectance.
URBIS_HD inline Vec3f glassTransmission(const Material& glass, float cosine) {
    return glass.albedo * (1.0f - glassFresnel(glass, cosine));
}

/// w of the windows' glass plane (wall coordinates).
URBIS_HD inline float glassPlaneW(const WallRecord& wall) { return -wall.reveal; }

/// Most tries of a lit-cell pick (windowPickTries).
inline constexpr uint32_t kMaxWindowPickTries = 32;

/// How many uniform tries over the tile's `cells` a pick among its `lit` cells makes: enough that
/// all miss with a chance of about e^-3 (5 %), at most kMaxWindowPickTries. Integer arithmetic, so
/// that the sampler and the pdf agree on both backends.
URBIS_HD inline uint32_t windowPickTries(uint32_t cells, uint32_t lit) {
    return lit == 0 ? 0u : (3u * cells + lit - 1u) / lit < kMaxWindowPickTries ? (3u * cells + lit - 1u) / lit : kMaxWindowPickTries;
}

/// Probability with which the pick of windowPickCell returns one given lit cell of a tile of `cells`
/// cells, `lit` of them lit: K uniform tries keep the first lit cell, so a lit cell comes out with
/// (1 - (1 - p)^K) / lit, p = lit / cells (all K miss otherwise: no sample).
URBIS_HD inline float windowPickPmf(uint32_t cells, uint32_t lit) {
    if (lit == 0 || cells == 0) return 0.0f;
    const float miss = 1.0f - float(lit) / float(cells);
    return (1.0f - powf(miss, float(windowPickTries(cells, lit)))) / float(lit);
}

/// Picks a lit cell of `wall`'s tile (`lit`: its lit cells, the light record's litCells) with the
/// uniform number u: the first try takes u's cell, later tries draw from a hash of u; the first
/// lit one is kept. False when every try finds an unlit cell. Fills the cell's floor and slot.
URBIS_HD inline bool windowPickCell(const WallRecord& wall, uint32_t lit, float u, uint32_t& floor, uint32_t& slot) {
    const uint32_t n = tileCellCount(wall), across = uint32_t(wall.tileSlotEnd() - int(wall.slot0));
    const uint32_t tries = n == 0 ? 0u : windowPickTries(n, lit);
    HashStream more{hash2(uint32_t(u * 16777216.0f), 0x5bd1e995u)};
    for (uint32_t t = 0; t < tries; ++t) {
        const float x = t == 0 ? u : more.uniform();
        const uint32_t k = uint32_t(fminf(x * float(n), float(n - 1)));
        floor = wall.floor0 + k / across;
        slot = wall.slot0 + k % across;
        if (cellDraws(wall, floor, slot).lit) return true;
    }
    return false;
}

/// A lit window of `wall` (`lit`: its tile's lit cells) seen from `from` with three uniform
/// numbers: a lit cell (windowPickCell), a uniform point of its glass. Fills the unit direction, the
/// distance, the solid-angle pdf and the radiance arriving through the pane (`room`: the lit room's
/// emission, `glass`: the pane's material). Only from in front of the glass plane.
URBIS_HD inline bool sampleWallWindows(const WallRecord& wall, uint32_t lit, Vec3f room, const Material& glass, Vec3f from,
                                       float u0, float u1, float u2, Vec3f& dir, float& distance, float& pdf, Vec3f& radiance) {
    uint32_t floor, slot;
    if (!windowPickCell(wall, lit, u0, floor, slot)) return false;
    const WindowRect r = windowRect(wall, cellLayout(wall, floor, slot));
    const float u = r.u0 + (r.u1 - r.u0) * u1, v = r.v0 + (r.v1 - r.v0) * u2;
    const Vec3f toPoint = wall.worldFromWall(u, v, glassPlaneW(wall)) - from;
    distance = length(toPoint);
    if (!(distance > 0.0f)) return false;
    dir = toPoint / distance;
    const float cosine = -dot(dir, wall.normal);
    if (!(cosine > 0.0f) || !(r.area() > 0.0f)) return false;
    pdf = distance * distance * windowPickPmf(tileCellCount(wall), lit) / (cosine * r.area());
    radiance = windowRadiance(windowLook(wall, floor, slot), r, room, u, v) * glassTransmission(glass, cosine);
    return true;
}

/// Solid-angle pdf with which sampleWallWindows returns unit direction `dir` from `from`: where the
/// ray meets the glass plane in front of it, inside the glass of a lit cell of the tile.
URBIS_HD inline float wallWindowsPdf(const WallRecord& wall, uint32_t lit, Vec3f from, Vec3f dir) {
    const float cosine = -dot(dir, wall.normal);
    const float height = dot(from - wall.origin, wall.normal) - glassPlaneW(wall);
    if (!(cosine > 0.0f) || !(height > 0.0f)) return 0.0f;
    const float t = height / cosine;
    const Vec3f rel = from + dir * t - wall.origin;
    const float u = dot(rel, wall.axisU), v = rel.y;
    const float fs = floorf((u - wall.gridU) / wall.slotWidth), ff = floorf((v - wall.gridV) / wall.floorHeight);
    if (!(fs >= float(wall.slot0) && fs < float(wall.tileSlotEnd()) && ff >= float(wall.floor0) &&
          ff < float(wall.tileFloorEnd())))
        return 0.0f;
    const CellLayout c = cellLayout(wall, uint32_t(ff), uint32_t(fs));
    const WindowRect r = windowRect(wall, c);
    if (!cellLit(wall, c) || u < r.u0 || u > r.u1 || v < r.v0 || v > r.v1 || !(r.area() > 0.0f)) return 0.0f;
    return t * t * windowPickPmf(tileCellCount(wall), lit) / (cosine * r.area());
}

/// The radiance a lit room of `wall` shows to a ray with unit direction `dir` through `origin` that
/// meets it at wall coordinates `hitUv`: the room's cell, its look at the point where the ray's
/// line crosses the glass plane (where sampleWallWindows evaluates it).
URBIS_HD inline Vec3f litRoomRadiance(const WallRecord& wall, Vec3f room, Vec3f origin, Vec3f dir, Vec2f hitUv) {
    const float cols = float(wall.slots) - 1.0f, rows = float(wall.floors) - 1.0f;
    const uint32_t slot = uint32_t(fminf(fmaxf(floorf((hitUv.x - wall.gridU) / wall.slotWidth), 0.0f), cols));
    const uint32_t floor = uint32_t(fminf(fmaxf(floorf((hitUv.y - wall.gridV) / wall.floorHeight), 0.0f), rows));
    const float dn = dot(dir, wall.normal);
    Vec2f at = hitUv;
    if (fabsf(dn) > 1e-6f) {
        const Vec3f rel = origin - wall.origin;
        const Vec3f p = rel + dir * ((glassPlaneW(wall) - dot(rel, wall.normal)) / dn);
        at = {dot(p, wall.axisU), p.y};
    }
    const CellLayout c = cellLayout(wall, floor, slot);
    return windowRadiance(windowLook(wall, floor, slot), windowRect(wall, c), room, at.x, at.y);
}

/// What the light build needs of a wall record's lit windows, from one walk over its tile.
struct WallWindowsTotals {
    float power = 0;        ///< expected flux: windowPower summed over the lit cells
    uint32_t litCells = 0;
};

/// The lit windows of a wall record's tile, counted and their expected flux summed.
URBIS_HD inline WallWindowsTotals wallWindowsTotals(const WallRecord& wall, Vec3f room) {
    WallWindowsTotals out;
    for (int f = int(wall.floor0); f < wall.tileFloorEnd(); ++f)
        for (int s = int(wall.slot0); s < wall.tileSlotEnd(); ++s) {
            const CellLayout c = cellLayout(wall, uint32_t(f), uint32_t(s));
            if (!cellLit(wall, c)) continue;
            out.power += windowPower(windowLook(wall, uint32_t(f), uint32_t(s)), windowRect(wall, c), room);
            ++out.litCells;
        }
    return out;
}

/// Bounds of a wall record's lit windows for the light BVH: the tile's glass plane, its flux `phi`,
/// one-sided about the outward normal with a hemisphere of emission (a Lambertian plane).
URBIS_HD inline LightBounds wallWindowsLightBounds(const WallRecord& wall, float phi) {
    LightBounds b;
    const float w = glassPlaneW(wall);
    b.bounds = {wall.worldFromWall(wall.tileU0(), wall.tileV0(), w), wall.worldFromWall(wall.tileU0(), wall.tileV0(), w)};
    b.bounds.extend(wall.worldFromWall(wall.tileU1(), wall.tileV1(), w));
    b.axis = wall.normal;
    b.cosThetaO = 1.0f;
    b.cosThetaE = 0.0f;
    b.phi = phi;
    return b;
}

/// The lit room's emission and the pane's material of `wall`'s facade.
URBIS_HD inline Vec3f litRoomEmission(const SceneView& scene, const WallRecord& wall) {
    return scene.materials[wall.facadeMaterials + uint32_t(FacadeMaterial::RoomLit)].emission;
}
URBIS_HD inline const Material& glassMaterial(const SceneView& scene, const WallRecord& wall) {
    return scene.materials[wall.facadeMaterials + uint32_t(FacadeMaterial::Glass)];
}

/// The lit windows of each wall record (a tile) as a light kind, one light per wall record, at dusk
/// and at night. Walls emit through it (KindIntersector<WallRecord>::Emitter): their lit rooms, which
/// a BSDF sample reaches through a pane, so MIS weighs what such a path finds (kFoundThroughPanes,
/// BounceInfo::windowPath in integrators/path_tracer.h).
struct WindowLight {
    static constexpr bool kInfinite = false, kMisWeighs = true, kFoundThroughPanes = true;
    static constexpr bool kPickDraw = true, kPointDraws = true;  ///< a lit cell, a point of its glass

    URBIS_HD static bool sample(const SceneView& scene, const LightRecord& light, Vec3f from, float u0, float u1,
                                float u2, LightSample& s) {
        const WallRecord& wall = scene.walls[light.index];
        return sampleWallWindows(wall, light.litCells, litRoomEmission(scene, wall), glassMaterial(scene, wall), from, u0,
                                 u1, u2, s.dir, s.distance, s.pdf, s.radiance);
    }
    /// `dir` from the shading point `from`.
    URBIS_HD static float pdf(const SceneView& scene, const LightRecord& light, Vec3f from, Vec3f dir, float, float) {
        return wallWindowsPdf(scene.walls[light.index], light.litCells, from, dir);
    }
    /// A lit cell of the tile (windowPickCell, as the light sampler picks it), a uniform point of its
    /// glass, a cosine-distributed direction out of the wall, through the pane.
    URBIS_HD static bool emitPhoton(const SceneView& scene, const LightRecord& light, const PhotonNumbers& u,
                                    SampleStream& rng, float scale, EmittedPhoton& out) {
        const WallRecord& wall = scene.walls[light.index];
        uint32_t floor, slot;
        if (!windowPickCell(wall, light.litCells, u.u1, floor, slot)) return false;
        const CellLayout c = cellLayout(wall, floor, slot);
        const WindowRect r = windowRect(wall, c);
        if (!(r.area() > 0.0f)) return false;
        const float wu = r.u0 + (r.u1 - r.u0) * u.u2, wv = r.v0 + (r.v1 - r.v0) * u.u3;
        const Vec3f dir = Frame::fromZ(wall.normal).toWorld(sampleCosineHemisphere(u.u4, rng.draw()));
        out.ray = Ray{wall.worldFromWall(wu, wv, glassPlaneW(wall)) + wall.normal * 1e-3f, dir};
        out.power = windowRadiance(windowLook(wall, floor, slot), r, litRoomEmission(scene, wall), wu, wv) *
                    glassTransmission(glassMaterial(scene, wall), dot(dir, wall.normal)) *
                    (kPi * r.area() / windowPickPmf(tileCellCount(wall), light.litCells) * scale);
        return true;
    }
    /// A lit room's look (litRoomRadiance), light-sampled where walls are lights; any other emitting
    /// part of a wall its material's emission.
    URBIS_HD static EmissionAtHit emittedAt(const SceneView& scene, const SurfaceHit& hit, const Material& material,
                                            const Ray& ray, Vec3f dir) {
        if (!(maxComponent(material.emission) > 0.0f)) return {};
        const WallRecord& wall = scene.walls[hit.index];
        if (hit.material != wall.facadeMaterials + uint32_t(FacadeMaterial::RoomLit)) return {material.emission};
        return {litRoomRadiance(wall, material.emission, ray.origin, dir, hit.uv), scene.lights.first<WindowLight>() != kNoLight};
    }
    URBIS_HD static uint32_t lightAt(const SceneView& scene, const SurfaceHit& hit) {
        return scene.lights.first<WindowLight>() + hit.index;
    }

    /// One light per wall record, in their order: its power the expected flux of its lit windows and
    /// its count of lit cells, which its sampler picks among (wallWindowsTotals, over TBB).
    static void addLights(LightListBuilder& b) {
        if (!b.night || !b.options.windows) return;
        const Scene& scene = b.scene;
        std::vector<WallWindowsTotals> totals(scene.walls.size());
        b.parallelFor(scene.walls.size(), [&](size_t i) {
            const WallRecord& wall = scene.walls[i];
            totals[i] = wallWindowsTotals(wall, scene.materials[wall.facadeMaterials + uint32_t(FacadeMaterial::RoomLit)].emission);
        });
        for (uint32_t i = 0; i < scene.walls.size(); ++i) b.add(kLightKindOf<WindowLight>, i, totals[i].power, totals[i].litCells);
    }
    static LightBounds bounds(const Scene& scene, const LightRecord& light) {
        return wallWindowsLightBounds(scene.walls[light.index], light.power);
    }
    static float photonFlux(const SceneView&, const LightRecord& light, float) { return light.power; }
};

} // namespace urbis
