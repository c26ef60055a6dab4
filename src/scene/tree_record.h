// A tree: the record of the tree kind (host+device POD). Its trunk, branches and noise-displaced
// crown are a signed distance function (geometry/tree_sdf.h) built from these few numbers when a ray
// reaches the tree's box, and sphere traced there (geometry/tree_intersect.h), so a tree costs 52
// bytes instead of the few hundred triangles of its twin.
#pragma once

#include "math/bounds.h"
#include "math/vec.h"

#include <cstdint>

namespace urbis {

/// The crown's shape: an ellipsoid on a trunk with branches, or a tiered cone round a trunk to its tip.
enum class TreeShape : uint8_t { Broadleaf, Conifer };

/// Materials a tree uses, at TreeRecord::material + index (nature/tree_materials.h gives them).
enum class TreeMaterial : uint32_t { Bark, Leaves };

/// Tree coordinates: metres from the trunk's foot, y up, axes parallel to the world's.
struct TreeRecord {
    Vec3f base;                   ///< world position of the trunk's foot (on the ground: a terrain lifts it)
    float height = 10.0f;         ///< m, of the crown's top above the foot
    float crownRadius = 3.0f;     ///< m, the crown's horizontal radius before displacement
    float crownBase = 3.5f;       ///< m, height of the crown's bottom above the foot
    float trunkRadius = 0.15f;    ///< m, at the foot
    /// The crown's displacement: noise of this amplitude (m) and frequency (1/m) added to its distance.
    float roughness = 0.5f;
    float frequency = 1.2f;
    uint32_t seed = 0;            ///< branches' directions and the noise's offset
    uint32_t object = 0;          ///< object id
    uint32_t material = 0;        ///< first of TreeMaterial's materials
    TreeShape shape = TreeShape::Broadleaf;

    /// Cost of testing one, in triangles, for the surface area heuristic: a sphere trace of some
    /// 20 to 60 steps, each a few capsules and a value noise, so each tree has a leaf of its own
    /// (tested deferred on the GPU, as walls and lamps are).
    static constexpr uint32_t kBvhCost = 24;
};

static_assert(sizeof(TreeRecord) <= 64, "a tree record is meant to stay small");

/// World bounds of everything the tree's distance function can reach (geometry/tree_sdf.h's
/// treeLocalBounds), widened by a millimetre and a relative margin for the rounding of world coordinates.
Bounds3f primBounds(const TreeRecord& tree);

} // namespace urbis
