// Catmull-Rom splines through control points, parameterised by knot spacing |p_{i+1} - p_i|^alpha:
// alpha 0 the uniform spline, 0.5 the centripetal one (no cusps or self-intersections within a
// segment: Yuksel, Schaefer and Keyser, "Parameterization and applications of Catmull-Rom curves",
// CAD 2011), evaluated by the Barry-Goldman pyramid. Host only (camera paths).
#pragma once

#include "math/vec.h"

#include <cmath>

namespace urbis {

/// The segment from p1 to p2 of the Catmull-Rom spline through p0, p1, p2, p3 at u in [0, 1], with
/// knots spaced by distance^alpha. u = 0 gives p1 and u = 1 gives p2 exactly. Coincident points
/// get a tiny knot step, so a camera that stays put (p1 = p2) stays exactly there.
inline Vec3f catmullRom(Vec3f p0, Vec3f p1, Vec3f p2, Vec3f p3, float u, float alpha) {
    if (u <= 0.0f) return p1;
    if (u >= 1.0f) return p2;
    if (p1.x == p2.x && p1.y == p2.y && p1.z == p2.z) return p1;
    const auto step = [alpha](Vec3f a, Vec3f b) { return std::fmax(std::pow(length(b - a), alpha), 1e-4f); };
    const float t0 = 0.0f, t1 = t0 + step(p0, p1), t2 = t1 + step(p1, p2), t3 = t2 + step(p2, p3);
    const float t = t1 + u * (t2 - t1);
    const auto blend = [t](Vec3f a, Vec3f b, float ta, float tb) { return a * ((tb - t) / (tb - ta)) + b * ((t - ta) / (tb - ta)); };
    const Vec3f a1 = blend(p0, p1, t0, t1), a2 = blend(p1, p2, t1, t2), a3 = blend(p2, p3, t2, t3);
    const Vec3f b1 = blend(a1, a2, t0, t2), b2 = blend(a2, a3, t1, t3);
    return blend(b1, b2, t1, t2);
}

/// The control point before the first (or after the last) of a spline: `end` mirrored through
/// `next`'s reflection, so the end segment leaves `end` heading straight for `next`.
inline Vec3f mirroredEnd(Vec3f end, Vec3f next) { return end * 2.0f - next; }

} // namespace urbis
