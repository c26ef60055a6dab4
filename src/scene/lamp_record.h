// A street lamp: the record of the lamp kind (host+device POD). Its pole, arm, head and glass are
// a few analytic pieces (scene/lamp_pieces.h) made from this record when a ray needs them, so a lamp
// costs 56 bytes instead of the thousand or so triangles of its twin.
#pragma once

#include "math/bounds.h"
#include "math/vec.h"

#include <cstdint>

namespace urbis {

/// The head's shape (the model's LampHead, in its order).
enum class LampShape : uint8_t { Cobra, Globe, Lantern, Cone, Flat };

/// Materials a lamp uses, at LampRecord::material + index (StreetMaterial::LampMetal's order).
enum class LampMaterial : uint32_t { Metal, Housing, Glass };

/// Lamp coordinates (metres): u along the arm (the way the head leans), y up from the pole's foot,
/// w to the arm's side. world = base + arm * u + (0, y, 0) + side * w, arm = (armX, 0, armZ) and
/// side = (-armZ, 0, armX).
struct LampRecord {
    Vec3f base;                  ///< world position of the pole's foot
    float height = 6.0f;         ///< of the light above the foot: the arm's axis, or a post-top head's bottom
    float armX = 1.0f, armZ = 0.0f;  ///< unit, horizontal: where the arm (and the head) points
    float armLength = 0.0f;      ///< from the pole's axis to the head's centre; 0: the head sits on the pole
    float poleRadius = 0.07f;    ///< at the foot; 0: no pole (a lamp on a wall or a wire)
    float headSize = 0.6f;       ///< the head's main dimension (lamp_pieces.h gives each shape's proportions)
    uint32_t object = 0;         ///< object id
    uint32_t material = 0;       ///< first of LampMaterial's materials
    /// The light, for the night (not used as a light by day): the colour temperature of its
    /// blackbody (lampColour in scene/lamp_emission.h) and its luminous flux.
    float colourTemperature = 4000.0f;   ///< K
    float luminousFlux = 10000.0f;       ///< lm, all of its lights together
    LampShape shape = LampShape::Cobra;

    /// Cost of testing one, in triangles, for the surface area heuristic: above one, so each lamp
    /// has a leaf of its own (leaves hold one kind), which the GPU tests deferred like a wall's.
    /// A lamp is up to four quadrics with their caps; docs/streets.md has the measurements.
    static constexpr uint32_t kBvhCost = 4;

    URBIS_HD Vec3f armAxis() const { return {armX, 0.0f, armZ}; }
    URBIS_HD Vec3f sideAxis() const { return {-armZ, 0.0f, armX}; }
    /// World position of lamp coordinates (u, y, w).
    URBIS_HD Vec3f worldFromLamp(Vec3f p) const { return base + armAxis() * p.x + Vec3f{0, p.y, 0} + sideAxis() * p.z; }
};

static_assert(sizeof(LampRecord) <= 64, "a lamp record is meant to stay small");

/// World bounds of a lamp: the boxes of its pieces (scene/lamp_pieces.h), slightly widened.
Bounds3f primBounds(const LampRecord& lamp);

} // namespace urbis
