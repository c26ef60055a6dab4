// The sun as a light (host+device): directions uniform in solid angle over its disk.
#pragma once

#include "math/frame.h"
#include "math/sampling.h"
#include "scene/sun.h"

namespace urbis {

URBIS_HD inline bool sunEnabled(const Sun& sun) { return maxComponent(sun.radiance) > 0.0f; }

/// A world direction towards the disk, uniform in solid angle (pdf: sunPdf).
URBIS_HD inline Vec3f sampleSunDirection(const Sun& sun, float u1, float u2) {
    return Frame::fromZ(sun.direction).toWorld(sampleUniformCone(u1, u2, sun.cosHalfAngle));
}

/// Solid-angle pdf of sampleSunDirection inside the disk: one over its solid angle.
URBIS_HD inline float sunPdf(const Sun& sun) { return uniformConePdf(sun.cosHalfAngle); }

/// Whether the unit direction `dir` lies in the disk.
URBIS_HD inline bool sunContains(const Sun& sun, Vec3f dir) { return dot(dir, sun.direction) >= sun.cosHalfAngle; }

} // namespace urbis
