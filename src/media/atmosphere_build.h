// The atmosphere's look-up tables, built on the host once per sun position (Hillaire 2020 § 5): the
// transmittance table, the multiple-scattering table and the sky view table (media/atmosphere_lut.h
// says how each is laid out). They are arrays of the scene (scene_arrays.h), so both backends read the
// same tables.
#pragma once

#include "scene/scene.h"

#include <vector>

namespace urbis {

/// Transmittance to the top of the atmosphere over the table's (view zenith, radius) coordinates:
/// kTransmittanceLutWidth x kTransmittanceLutHeight texels, rows by radius.
std::vector<Vec3f> buildTransmittanceLut(const Atmosphere& a);

/// Hillaire 2020 § 5.5: Psi_ms = L_2nd / (1 - f_ms) over (sun zenith cosine, radius), from 64 directions
/// over the sphere around each texel's point, each integrated with an isotropic phase and the lit
/// ground: kMultiScatteringLutSize squared texels, rows by radius, per unit of solar irradiance.
std::vector<Vec3f> buildMultiScatteringLut(const Atmosphere& a, const std::vector<Vec3f>& transmittance);

/// The sky's radiance seen from the world's origin under `a.sunDirection` and `a.solarIrradiance`
/// (single scattering from the transmittance table, multiple scattering from `multiScattering`, and the
/// lit ground below the horizon) over the sky view table's coordinates: kSkyViewLutWidth x
/// kSkyViewLutHeight texels, rows by latitude.
std::vector<Vec3f> buildSkyViewLut(const Atmosphere& a, const std::vector<Vec3f>& transmittance,
                                   const std::vector<Vec3f>& multiScattering);

/// Sets up the scene's atmosphere for its sun, where its sky's model is Atmosphere (otherwise it
/// clears the tables): the atmosphere takes the sun's direction and its irradiance (the sun's radiance
/// over its disk, taken as at the top of the atmosphere), the three tables are built, and the sun's
/// radiance takes the transmittance towards it (reddened near the horizon, zero below it). Call once
/// after the sun and sky are set, before buildLights. Without `multipleScattering` the tables hold
/// single scattering alone (the tests compare that with a brute-force integral). `tablesBuiltFor`: the
/// atmosphere the scene's tables were last built for with multiple scattering, if any; where its medium
/// is the scene's, the transmittance and multiple-scattering tables are kept (they do not depend on the
/// sun) and only the sky view table is built again: a sequence whose time of day moves relights each
/// frame in a fraction of the time, with the same bits.
void buildAtmosphere(Scene& scene, bool multipleScattering = true, const Atmosphere* tablesBuiltFor = nullptr);

/// Whether `a` and `b` are the same medium: every field but the sun's direction and irradiance.
bool sameMedium(const Atmosphere& a, const Atmosphere& b);

} // namespace urbis
