// Model trees -> the tree kind's records (host): sizes from the tags (`height`, `diameter_crown`,
// `circumference`) or seeded variations of the defaults, the shape by `leaf_type`, the leaves'
// material by shape, `leaf_cycle` and season, and the materials themselves.
#pragma once

#include "model/city_model.h"
#include "nature/tree_options.h"
#include "scene/material.h"
#include "scene/tree_growth.h"

#include <cstdint>
#include <vector>

namespace urbis {

/// The materials of TreeLeaves, two per pair: the bark, then the leaves (summer's broadleaves at
/// 0.8, 1 and 1.2 times leafAlbedo).
std::vector<Material> treeMaterials(const TreeOptions& options);

/// The variation and roughness that `options` give untagged trees.
TreeStyle treeStyleOf(const TreeOptions& options);

/// The record of `tree` (model metres: x east, y north; world x, -z), its foot on the ground plane
/// (y = 0), grown by grownTreeRecord from its tags: `height`, `diameter_crown`, `circumference`,
/// `leaf_type` and (in autumn) `leaf_cycle`. `key` seeds its variation and its crown's noise.
TreeRecord treeRecordOf(const Tree& tree, uint32_t key, const TreeOptions& options, uint32_t object, uint32_t firstMaterial);

} // namespace urbis
