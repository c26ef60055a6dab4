// What a cloud's droplet scatters towards the path from a light sample (host+device): the two-lobe
// phase function for single scattering, and at the path's last vertex Wrenninge's octaves for the
// orders of scattering the path can no longer follow (Wrenninge, Kulla and Lundqvist, "Oz: The Great
// and Volumetric", SIGGRAPH 2013 talk; Hillaire 2016, § 5.2): octave i scatters a^i of the light
// through b^i of the extinction with c^i of the anisotropy. A path that goes on scatters again by
// the phase function itself, so its light samples take the first octave alone and nothing counts twice.
#pragma once

#include "media/cloud_phase.h"
#include "media/cloud_tracking.h"

namespace urbis {

/// The octaves of a light sample at a droplet of `layer`, whose light travels at the scattering
/// angle of cosine `cosTheta` from the light to the viewer; `lastVertex`: all the layer's octaves
/// (else the first, the phase function itself, whose value is weight[0]).
URBIS_HD inline CloudOctaves cloudLightOctaves(const CloudLayer& layer, float cosTheta, bool lastVertex) {
    CloudOctaves o;
    o.count = lastVertex ? layer.octaves : 1u;
    float scattering = 1.0f, extinction = 1.0f, anisotropy = 1.0f;
    for (uint32_t i = 0; i < o.count; ++i) {
        o.weight[i] = scattering * cloudPhaseValue(cloudPhase(layer, anisotropy), cosTheta);
        o.extinction[i] = extinction;
        scattering *= layer.octaveScattering;
        extinction *= layer.octaveExtinction;
        anisotropy *= layer.octaveAnisotropy;
    }
    return o;
}

} // namespace urbis
