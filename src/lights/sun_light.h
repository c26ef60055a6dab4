// The sun as a light (host+device): directions uniform in solid angle over its disk. The moon is a
// disk of the same record (lights/moon_light.h): both kinds share DiskLightKind.
#pragma once

#include "lights/light_build.h"
#include "lights/light_sample.h"
#include "math/rng.h"
#include "math/sampling.h"
#include "media/planet_atmosphere.h"
#include "scene/scene_view.h"

#include <cmath>

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

/// The functions of a light kind that is a disk of directions (a Sun record), which
/// `Disk::disk(scene)` names: the sun and the moon. Infinite: sampled apart from the light BVH.
/// MIS does not weigh it: its disk (about 7e-5 sr) has a light-sampling pdf thousands of times any
/// BSDF's, where the power heuristic would give its light samples a weight of 1 to within
/// (p_bsdf / p_disk)^2, so they count in full and a BSDF sample that finds the disk counts nothing.
template <typename Disk>
struct DiskLightKind {
    static constexpr bool kInfinite = true, kMisWeighs = false, kFoundThroughPanes = false;
    static constexpr bool kPickDraw = false, kPointDraws = true;  ///< a direction: two numbers

    URBIS_HD static bool sample(const SceneView& scene, const LightRecord&, Vec3f from, float, float u1, float u2,
                                LightSample& s) {
        const Sun& disk = Disk::disk(scene);
        if (!sunEnabled(disk)) return false;
        s.dir = sampleSunDirection(disk, u1, u2);
        s.radiance = disk.radiance * diskTransmittanceFrom(scene, from, s.dir);
        s.pdf = sunPdf(disk);
        return true;
    }
    URBIS_HD static float pdf(const SceneView& scene, const LightRecord&, Vec3f, Vec3f dir, float, float) {
        const Sun& disk = Disk::disk(scene);
        return sunEnabled(disk) && sunContains(disk, dir) ? sunPdf(disk) : 0.0f;
    }
    /// A direction of the disk, a ray towards the scene's sphere through its disk (rayFromDisk).
    URBIS_HD static bool emitPhoton(const SceneView& scene, const LightRecord&, const PhotonNumbers& u, SampleStream&,
                                    float scale, EmittedPhoton& out) {
        const Sun& disk = Disk::disk(scene);
        if (!sunEnabled(disk)) return false;
        const Vec3f towards = sampleSunDirection(disk, u.u1, u.u2);
        const float r = scene.photons.radius;
        out.ray = rayFromDisk(scene.photons.centre, r, towards, u.u3, u.u4);
        out.power = disk.radiance * (kPi * r * r / sunPdf(disk) * scale);
        return true;
    }

    /// Adds `disk` where it shines: its power is its radiance times its solid angle through the
    /// sphere's disk. A disk wholly below the horizon of an infinite ground lights nothing above it:
    /// it stays out of the list, where its power would take nearly every light sample from the
    /// night's lamps and windows.
    static void addDisk(LightListBuilder& b, const Sun& disk) {
        const float sinHalfAngle = std::sqrt(std::fmax(0.0f, 1.0f - disk.cosHalfAngle * disk.cosHalfAngle));
        if (!b.scene.grounds.empty() && disk.direction.y < -sinHalfAngle) return;
        const double area = double(kPi) * b.radius * b.radius;
        b.add(kLightKindOf<Disk>, 0, float(area * luminance(disk.radiance) / double(sunPdf(disk))));
    }
    static LightBounds bounds(const Scene&, const LightRecord&) { return {}; }
    /// What its photons carry (emitPhoton): its radiance through the disk of the sphere of `radius`.
    static float photonFlux(const SceneView& scene, const LightRecord&, float radius) {
        const Sun& disk = Disk::disk(scene);
        return sunEnabled(disk) ? luminance(disk.radiance) / sunPdf(disk) * kPi * radius * radius : 0.0f;
    }
};

struct SunLight : DiskLightKind<SunLight> {
    URBIS_HD static const Sun& disk(const SceneView& scene) { return scene.sun; }

    static void addLights(LightListBuilder& b) {
        if (b.options.sun && sunEnabled(b.scene.sun)) addDisk(b, b.scene.sun);
    }
    /// The disk seen by a ray that meets nothing, but not by the camera ray (depth 0); around a
    /// planet through the atmosphere from `origin`.
    URBIS_HD static bool escaped(const SceneView& scene, Vec3f origin, Vec3f dir, uint32_t depth, Vec3f& radiance) {
        if (depth == 0 || !sunEnabled(scene.sun) || !sunContains(scene.sun, dir)) return false;
        radiance = scene.sun.radiance * diskTransmittanceFrom(scene, origin, dir);
        return true;
    }
};

} // namespace urbis
