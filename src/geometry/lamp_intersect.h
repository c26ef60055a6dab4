// Ray/street-lamp intersection (host+device): the ray is taken into lamp coordinates and moved along
// itself to the point nearest the lamp, then each of the lamp's pieces (scene/lamp_pieces.h) is
// solved analytically: truncated cones and spheres as quadrics, caps as planes. Moving the
// origin first keeps the quadrics' coefficients at the lamp's scale: from a camera 1 km away,
// |o|^2 rounds by more than a pole's radius squared (the cancellation "Precision Improvements for
// Ray/Sphere Intersection", E. Haines et al., Ray Tracing Gems 2019, ch. 7, avoids the same way).
// Everything that decides a hit uses urbis.h's exact operations, so both backends agree bit for bit.
#pragma once

#include "accel/bvh_traverse.h"
#include "math/ray.h"
#include "scene/lamp_pieces.h"

namespace urbis {

/// A hit on a lamp: distance, which piece and which of its faces (0 a frustum's side or the sphere,
/// 1 the low cap, 2 the high cap).
struct LampHit {
    float t = 0;
    uint32_t piece = 0, face = 0;
};

/// A ray in lamp coordinates whose origin lies `shift` along the original ray: t there is t - shift.
struct LampRay {
    Vec3f o, d, invD;
    float shift, tmin;

    URBIS_HD LampRay(const LampRecord& l, const Ray& ray) {
        const Vec3f rel{exactSub(ray.origin.x, l.base.x), exactSub(ray.origin.y, l.base.y), exactSub(ray.origin.z, l.base.z)};
        const Vec3f arm = l.armAxis(), side = l.sideAxis();
        const Vec3f o0{exactDot(rel, arm), rel.y, exactDot(rel, side)};
        d = {exactDot(ray.dir, arm), ray.dir.y, exactDot(ray.dir, side)};
        // 1 / d on each axis and 1 / |d|^2, from one division in a loop: each exact division is
        // some 90 instructions of GPU code.
        const float dd = exactDot(d, d);
        float invDD = 0.0f;
        URBIS_NO_UNROLL
        for (int a = 0; a < 4; ++a) {
            const float inverse = BvhRay::safeInverse(a < 3 ? d[a] : dd);
            if (a < 3) invD[a] = inverse;
            else invDD = inverse;
        }
        // The point of the ray nearest the middle of the lamp.
        const Vec3f toMiddle{exactSub(exactMul(0.5f, l.armLength), o0.x), exactSub(exactMul(0.5f, l.height), o0.y), -o0.z};
        shift = exactMul(exactDot(toMiddle, d), invDD);
        o = {exactMulAdd(shift, d.x, o0.x), exactMulAdd(shift, d.y, o0.y), exactMulAdd(shift, d.z, o0.z)};
        tmin = exactSub(ray.tmin, shift);
    }
};

URBIS_HD inline float exactSquare(float a) { return exactMul(a, a); }
/// a * b + c * d, each product rounded, then the sum.
URBIS_HD inline float exactDot2(float a, float b, float c, float d) { return exactAdd(exactMul(a, b), exactMul(c, d)); }

/// Tests a frustum or sphere piece in tmin < t < tmax (the lamp ray's t); on a hit shrinks tmax
/// and sets `face`. Both are one quadric about the piece's axis, in the radial offsets x, z and the
/// axial offset s from the piece's point a:
///   frustum  x^2 + z^2 - (r0 + k s)^2 = 0,  0 <= s <= length, with its caps;
///   sphere   x^2 + z^2 + s^2 - R^2 = 0,     s >= the cut's offset.
/// One solver for both keeps the GPU's code small (its render kernel is instruction-fetch bound).
URBIS_HD inline bool intersectLampQuadric(const LampPiece& p, const LampRay& r, float& tmax, uint32_t& face) {
    const bool sphere = p.shape == LampPieceShape::Sphere;
    const int ax = p.axis, rx = ax == 0 ? 1 : 0;   // the axis, and the radial axis besides w
    const float os = exactSub(r.o[ax], p.a[ax]), ds = r.d[ax];
    const float ox = exactSub(r.o[rx], p.a[rx]), dx = r.d[rx];
    const float oz = exactSub(r.o.z, p.a.z), dz = r.d.z;
    // The axial term: (k ds) t + (r0 + k os), subtracted squared for a frustum; s itself, added, for a sphere.
    const float k = sphere ? 1.0f : p.b.z, r0 = sphere ? 0.0f : p.b.y;
    const float axial0 = exactMulAdd(k, os, r0), axialD = exactMul(k, ds);
    const float sign = sphere ? 1.0f : -1.0f;
    const float sLo = sphere ? exactSub(p.b.y, p.a.y) : 0.0f, sHi = sphere ? 3.0e38f : p.b.x;
    bool found = false;
    if (p.faces & kLampSide) {
        const float A = exactAdd(exactDot2(dx, dx, dz, dz), exactMul(sign, exactSquare(axialD)));
        const float B = exactAdd(exactDot2(ox, dx, oz, dz), exactMul(sign, exactMul(axialD, axial0)));
        const float C = exactSub(exactAdd(exactDot2(ox, ox, oz, oz), exactMul(sign, exactSquare(axial0))),
                                 sphere ? exactSquare(p.b.x) : 0.0f);
        // A t^2 + 2 B t + C = 0.
        const float disc = exactSub(exactSquare(B), exactMul(A, C));
        if (disc >= 0.0f && A != 0.0f) {
            const float q = exactSqrt(disc), invA = exactDiv(1.0f, A);
            const float ta = exactMul(exactSub(-B, q), invA), tb = exactMul(exactAdd(-B, q), invA);
            float t = ta < tb ? ta : tb;
            URBIS_NO_UNROLL
            for (int root = 0; root < 2; ++root, t = ta < tb ? tb : ta) {
                const float s = exactMulAdd(t, ds, os);
                if (t > r.tmin && t < tmax && s >= sLo && s <= sHi) {
                    tmax = t;
                    face = 0;
                    found = true;
                    break;
                }
            }
        }
    }
    URBIS_NO_UNROLL
    for (uint32_t cap = 1; cap <= 2; ++cap) {
        if (!(p.faces & (cap == 1 ? kLampCapLow : kLampCapHigh))) continue;
        const float t = exactMul(exactSub(cap == 1 ? 0.0f : p.b.x, os), r.invD[ax]);
        if (!(t > r.tmin && t < tmax)) continue;
        const float x = exactMulAdd(t, dx, ox), z = exactMulAdd(t, dz, oz), radius = cap == 1 ? r0 : p.highRadius();
        if (exactDot2(x, x, z, z) > exactSquare(radius)) continue;
        tmax = t;
        face = cap;
        found = true;
    }
    return found;
}

/// Whether `ray` meets the lamp with ray.tmin < t < ray.tmax: then the closest such hit (with
/// anyHit, the first found).
URBIS_HD inline bool intersectLamp(const LampRecord& lamp, const Ray& ray, LampHit& hit, bool anyHit) {
    const LampRay r(lamp, ray);
    float tmax = exactSub(ray.tmax, r.shift);
    bool found = false;
    URBIS_NO_UNROLL
    for (int i = 0; i < kLampPieces; ++i) {
        const LampPiece p = lampPiece(lamp, i);
        if (p.shape == LampPieceShape::None) continue;
        uint32_t face = 0;
        if (!intersectLampQuadric(p, r, tmax, face)) continue;
        hit.piece = uint32_t(i);
        hit.face = face;
        found = true;
        if (anyHit) break;
    }
    if (!found) return false;
    hit.t = exactAdd(tmax, r.shift);
    return hit.t > ray.tmin && hit.t < ray.tmax;
}

/// The unit normal (lamp coordinates) of piece `p` at lamp point `q` on face `face`.
URBIS_HD inline Vec3f lampPieceNormal(const LampPiece& p, Vec3f q, uint32_t face) {
    Vec3f n;
    if (p.shape == LampPieceShape::Sphere) return normalize(q - p.a);
    if (face != 0) {
        n[p.axis] = face == 1 ? -1.0f : 1.0f;
        return n;
    }
    // The cone's gradient: radial (x, z), and -k (r0 + k s) along its axis.
    const int rx = p.axis == 0 ? 1 : 0;
    const float k = p.b.z, s = q[p.axis] - p.a[p.axis];
    n[rx] = q[rx] - p.a[rx];
    n.z = q.z - p.a.z;
    n[p.axis] = -k * (p.b.y + k * s);
    return normalize(n);
}

} // namespace urbis
