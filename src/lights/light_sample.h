// What every light kind's functions take and give (host+device): a light sample towards a shading
// point, a photon leaving a light, and the emission a ray finds where it hits a surface.
#pragma once

#include "math/constants.h"
#include "math/frame.h"
#include "math/ray.h"
#include "scene/material.h"

namespace urbis {

/// A direction towards a light from a shading point.
struct LightSample {
    Vec3f dir;                ///< unit, world space
    Vec3f radiance;           ///< arriving along -dir, before visibility
    float pdf = 0;            ///< solid angle, given that this light was chosen
    float distance = 3.0e38f; ///< to the point sampled; infinite lights: the largest float
};

/// A photon's first ray and its flux (renderer units, for one of `photonsPerPass`).
struct EmittedPhoton {
    Ray ray;
    Vec3f power;
    /// Whether its first hit is stored: its light is not light-sampled by the camera pass (the sky by
    /// day), so photons must carry its direct light too.
    bool depositFirst = false;
};

/// The four uniform numbers a photon's emission draws before its light's own (integrators/photon_emit.h).
struct PhotonNumbers {
    float u1, u2, u3, u4;
};

/// A ray from the disk of radius `radius` about `centre`, perpendicular to unit `towards` (where the
/// light is), that travels along -towards and starts outside the sphere: infinite lights reach every
/// point of the sphere through it, pi radius^2 of area.
URBIS_HD inline Ray rayFromDisk(Vec3f centre, float radius, Vec3f towards, float u1, float u2) {
    const Frame frame = Frame::fromZ(towards);
    const float r = radius * sqrtf(u1), phi = 2.0f * kPi * u2;
    const Vec3f origin = centre + towards * (1.01f * radius) + frame.x * (r * cosf(phi)) + frame.y * (r * sinf(phi));
    return Ray{origin, -towards};
}

/// What a ray finds emitted where it hits a primitive whose kind emits through a light kind
/// (KindIntersector<Record>::Emitter): the radiance, and whether that light kind's light samples
/// also reach it (then MIS weighs it, by the light the kind's lightAt names).
struct EmissionAtHit {
    Vec3f radiance;
    bool lightSampled = false;
};

/// A material's own emission: zero unless it emits.
URBIS_HD inline Vec3f materialEmission(const Material& material) {
    return maxComponent(material.emission) > 0.0f ? material.emission : Vec3f{};
}

} // namespace urbis
