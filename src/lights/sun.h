// The sun: a disk of uniform radiance with a finite angular radius (soft shadows), sampled by
// next-event estimation only (sky lookups exclude the disk, so nothing is counted twice).
#pragma once

#include "math/frame.h"
#include "math/sampling.h"

namespace urbis {

struct Sun {
    Vec3f direction{0, 1, 0};  ///< unit, world space, towards the sun
    Vec3f radiance{0, 0, 0};   ///< per steradian inside the disk; zero turns the sun off
    float cosHalfAngle = 1.0f; ///< cosine of the angular radius

    URBIS_HD bool enabled() const { return maxComponent(radiance) > 0.0f; }
    /// A direction towards the disk, uniform in solid angle; its pdf is 1 / solid angle.
    URBIS_HD Vec3f sampleDirection(float u1, float u2) const {
        return Frame::fromZ(direction).toWorld(sampleUniformCone(u1, u2, cosHalfAngle));
    }
    URBIS_HD float pdf() const { return uniformConePdf(cosHalfAngle); }
    URBIS_HD bool contains(Vec3f unitDir) const { return fusedDot(unitDir, direction) >= cosHalfAngle; }
};

/// A sun at elevation and azimuth (degrees; azimuth clockwise from north) whose disk of the given
/// angular radius (degrees) gives `irradiance` on a surface facing it. World: x east, y up, z south.
Sun makeSun(float elevationDeg, float azimuthDeg, float angularRadiusDeg, Vec3f irradiance);

/// The world-space unit direction for an elevation and azimuth in degrees (azimuth clockwise from north).
Vec3f directionFromElevationAzimuth(float elevationDeg, float azimuthDeg);

} // namespace urbis
