// Tracking through a cloud layer (host+device), unbiased against a majorant: delta tracking samples
// where a path's ray collides with a droplet, ratio tracking estimates a shadow ray's transmittance
// (Woodcock et al. 1965; Novák, Selle and Jarosz, "Residual Ratio Tracking for Estimating Attenuation
// in Participating Media", SIGGRAPH Asia 2014, § 3-4). The majorant is per coverage cell
// and height band (cloudMajorant): a walk over the cells the ray crosses (Amanatides and Woo 1987) skips the
// cloudless ones and restarts the exponential steps at each cell's edge, which the exponential's
// memorylessness allows.
#pragma once

#include "math/ray.h"
#include "math/rng.h"
#include "media/cloud_shell.h"

namespace urbis {

/// The part [t0, t1] (metres along the unit `dir` from `origin`, within [0, tmax]) of a ray inside
/// the layer's slab and within its radius. False where the ray misses it.
URBIS_HD inline bool clipToCloudLayer(const CloudLayer& layer, Vec3f origin, Vec3f dir, float tmax, float& t0, float& t1) {
    t0 = 0.0f;
    t1 = tmax;
    const float top = layer.bottom + layer.thickness;
    if (dir.y != 0.0f) {
        const float a = (layer.bottom - origin.y) / dir.y, b = (top - origin.y) / dir.y;
        t0 = fmaxf(t0, fminf(a, b));
        t1 = fminf(t1, fmaxf(a, b));
    } else if (!(origin.y > layer.bottom && origin.y < top)) {
        return false;
    }
    // The cylinder of the radius about the y axis: |origin.xz + t dir.xz| <= radius.
    const float a = dir.x * dir.x + dir.z * dir.z, b = origin.x * dir.x + origin.z * dir.z;
    const float c = origin.x * origin.x + origin.z * origin.z - layer.radius * layer.radius;
    if (a > 0.0f) {
        const float disc = b * b - a * c;
        if (!(disc > 0.0f)) return false;
        const float root = sqrtf(disc);
        t0 = fmaxf(t0, (-b - root) / a);
        t1 = fminf(t1, (-b + root) / a);
    } else if (c > 0.0f) {
        return false;
    }
    return t0 < t1;
}

/// One axis of the walk over cells: the cell the ray is in, and where it crosses into the next.
struct CloudWalkAxis {
    int32_t index, step;
    float next, delta;   ///< metres along the ray: the next crossing, and between crossings

    /// The axis of coordinate `x` (in cells) at distance t0, changing by `dx` cells per metre.
    URBIS_HD static CloudWalkAxis at(float x, float dx, float t0) {
        const float inf = 3.0e38f;
        const int32_t i = int32_t(floorf(x));
        return {i, dx > 0.0f ? 1 : -1, dx != 0.0f ? t0 + (float(i + (dx > 0.0f)) - x) / dx : inf,
                dx != 0.0f ? 1.0f / fabsf(dx) : inf};
    }
    URBIS_HD void advance() {
        index += step;
        next += delta;
    }
};

/// Calls visit(ta, tb, majorant) for each piece [ta, tb] of [t0, t1] (metres along the unit `dir`)
/// in one coverage cell and height band of nonzero majorant (cloudMajorant), in order along the ray,
/// until visit returns false: a 3D DDA (Amanatides and Woo 1987) over the cells and the bands.
template <typename Visit>
URBIS_HD inline void forEachCloudCell(const CloudLayer& layer, ArrayView<float> majorants, Vec3f origin, Vec3f dir,
                                      float t0, float t1, Visit&& visit) {
    const float cell = layer.coverageCell, band = layer.thickness / float(kCloudBands);
    const Vec3f start = origin + dir * t0;
    CloudWalkAxis x = CloudWalkAxis::at((start.x - layer.wind.x) / cell, dir.x / cell, t0);
    CloudWalkAxis y = CloudWalkAxis::at((start.y - layer.bottom) / band, dir.y / band, t0);
    CloudWalkAxis z = CloudWalkAxis::at((start.z - layer.wind.z) / cell, dir.z / cell, t0);
    for (float t = t0; t < t1;) {
        const float end = fminf(t1, fminf(x.next, fminf(y.next, z.next)));
        const float majorant = cloudMajorant(layer, majorants, x.index, z.index, y.index);
        if (majorant > 0.0f && !visit(t, end, majorant)) return;
        t = end;
        if (x.next <= y.next && x.next <= z.next) x.advance();
        else if (y.next <= z.next) y.advance();
        else z.advance();
    }
}

/// Delta tracking over [ta, tb] under a constant `majorant` (per metre) of `density(t)`: advances `t`
/// by exponential steps and returns true at the first real collision (probability density(t) /
/// majorant), false once past tb (`t` is then undefined).
template <typename Density>
URBIS_HD inline bool deltaTrack(Density&& density, float majorant, float ta, float tb, SampleStream& rng, float& t) {
    for (t = ta;;) {
        t -= logf(1.0f - rng.draw()) / majorant;
        if (t >= tb) return false;
        if (rng.draw() * majorant < density(t)) return true;
    }
}

/// Extinction scales (Wrenninge's octaves) and how much of the light each carries, for one shadow ray.
struct CloudOctaves {
    float weight[kCloudMaxOctaves] = {1.0f};      ///< the light's factor through each octave's transmittance
    float extinction[kCloudMaxOctaves] = {1.0f};  ///< the scale of the extinction that octave sees
    uint32_t count = 1;
};

/// Ratio tracking over [ta, tb] under a constant `majorant` of `density(t)`: at each tentative
/// collision every octave's transmittance T[i] takes 1 - extinction[i] density / majorant. Russian
/// roulette ends walks whose largest T falls below 0.2 (survivors divide by their probability), so the
/// estimate stays unbiased. Returns false when the walk has ended (every T is then 0).
template <typename Density>
URBIS_HD inline bool ratioTrack(Density&& density, float majorant, float ta, float tb, const CloudOctaves& octaves,
                                float* T, SampleStream& rng) {
    for (float t = ta;;) {
        t -= logf(1.0f - rng.draw()) / majorant;
        if (t >= tb) return true;
        const float ratio = density(t) / majorant;
        float largest = 0;
        for (uint32_t i = 0; i < octaves.count; ++i) {
            T[i] *= 1.0f - octaves.extinction[i] * ratio;
            largest = fmaxf(largest, T[i]);
        }
        if (largest < 0.2f) {
            const float survival = largest * 5.0f;
            if (!(rng.draw() < survival)) {
                for (uint32_t i = 0; i < octaves.count; ++i) T[i] = 0.0f;
                return false;
            }
            for (uint32_t i = 0; i < octaves.count; ++i) T[i] /= survival;
        }
    }
}

/// Calls visit(ta, tb, majorant, density) for each piece [ta, tb] (metres along the unit `dir` from
/// `origin`, within [0, tmax]) of the scene's clouds along the ray, in order, until visit returns
/// false; density(s) is the extinction at origin + s dir. In a city the flat layer's cells and bands
/// (forEachCloudCell); around a planet the ray's pieces in its shell (media/cloud_shell.h) under
/// the layer's density, which bounds the shell's everywhere.
template <typename Visit>
URBIS_HD inline void forEachCloudPiece(const SceneView& scene, Vec3f origin, Vec3f dir, float tmax, Visit&& visit) {
    if (!hasClouds(scene)) return;
    const CloudLayer& layer = scene.cloudLayers[0];
    const CloudTables tables = cloudTables(scene);
    if (const PlanetRecord* pl = scenePlanet(scene)) {
        const auto density = [&](float s) { return cloudShellDensity(layer, tables, *pl, origin + dir * s); };
        float t0[2], t1[2];
        const uint32_t n = clipToCloudShell(layer, *pl, origin, dir, tmax, t0, t1);
        for (uint32_t i = 0; i < n; ++i)
            if (!visit(t0[i], t1[i], layer.density, density)) return;
        return;
    }
    float t0, t1;
    if (!clipToCloudLayer(layer, origin, dir, tmax, t0, t1)) return;
    const auto density = [&](float s) {
        const Vec3f p = origin + dir * s;
        return cloudDensity(layer, tables, p, p.y);
    };
    forEachCloudCell(layer, tables.majorants, origin, dir, t0, t1,
                     [&](float ta, float tb, float majorant) { return visit(ta, tb, majorant, density); });
}

/// Delta tracking of `ray` (world; direction of any length) through the scene's clouds up to its
/// parameter `tmax`: true where it collides with a droplet first, at parameter `t`.
URBIS_HD inline bool cloudCollision(const SceneView& scene, const Ray& ray, float tmax, SampleStream& rng, float& t) {
    if (!hasClouds(scene)) return false;
    const float len = length(ray.dir);
    bool collided = false;
    forEachCloudPiece(scene, ray.origin, ray.dir / len, fminf(tmax * len, 3.0e38f),
                      [&](float ta, float tb, float majorant, const auto& density) {
                          float s;
                          collided = deltaTrack(density, majorant, ta, tb, rng, s);
                          if (collided) t = s / len;
                          return !collided;
                      });
    return collided;
}

/// Ratio-tracked transmittance of the scene's clouds along `ray` (world; direction of any length) up
/// to its tmax, as the octaves' weighted sum: sum of weight[i] T[i]. With one octave of weight 1
/// (a surface's shadow ray), the transmittance itself; 1 where there are no clouds.
URBIS_HD inline float cloudTransmittance(const SceneView& scene, const Ray& ray, const CloudOctaves& octaves,
                                         SampleStream& rng) {
    float T[kCloudMaxOctaves] = {1.0f, 1.0f, 1.0f, 1.0f};
    if (hasClouds(scene)) {
        const float len = length(ray.dir);
        forEachCloudPiece(scene, ray.origin, ray.dir / len, fminf(ray.tmax * len, 3.0e38f),
                          [&](float ta, float tb, float majorant, const auto& density) {
                              return ratioTrack(density, majorant, ta, tb, octaves, T, rng);
                          });
    }
    float sum = 0;
    for (uint32_t i = 0; i < octaves.count; ++i) sum += octaves.weight[i] * T[i];
    return sum;
}

} // namespace urbis
