// The ground: the record of the ground kind (host+device POD), a horizontal rectangle that the
// intersector meets analytically. Two stored triangles of that size would put vertices 1e5 m from
// every hit and lose the precision that spawned rays need. A heightfield replaces it later.
#pragma once

#include "math/bounds.h"

#include <cstdint>

namespace urbis {

/// Half the side of the default ground around the city, metres: its edge lies 0.12 degrees below
/// the horizon seen from 2 km up, under a pixel of a 1080p frame at a 40 degree field of view.
inline constexpr float kGroundHalfExtent = 1.0e6f;

/// The rectangle x in [x0, x1], z in [z0, z1] at world height y = height, seen from above
/// (geometry/ground_intersect.h).
struct GroundRecord {
    float height = 0.0f;             ///< world y, metres
    float x0 = -kGroundHalfExtent, z0 = -kGroundHalfExtent;
    float x1 = kGroundHalfExtent, z1 = kGroundHalfExtent;
    uint32_t material = 0;

    /// Cheap as a triangle; hung from the BVH's root (attachLeavesAtRoot), since its box is the world's.
    static constexpr uint32_t kBvhCost = 1;
    static constexpr bool kBvhAtRoot = true;

    /// The ground of `material` at `height`, kGroundHalfExtent around (cx, cz).
    static GroundRecord around(float cx, float cz, float height, uint32_t material) {
        return {height, cx - kGroundHalfExtent, cz - kGroundHalfExtent, cx + kGroundHalfExtent, cz + kGroundHalfExtent,
                material};
    }
};

/// World bounds of the ground: flat in y.
inline Bounds3f primBounds(const GroundRecord& g) { return {{g.x0, g.height, g.z0}, {g.x1, g.height, g.z1}}; }

} // namespace urbis
