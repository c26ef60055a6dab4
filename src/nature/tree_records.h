// Model trees -> the tree kind's records (host): sizes from the tags (`height`, `diameter_crown`,
// `circumference`) or seeded variations of the defaults, the shape by `leaf_type`, the leaves'
// material by shape, `leaf_cycle` and season, and the materials themselves.
#pragma once

#include "model/city_model.h"
#include "nature/tree_options.h"
#include "scene/material.h"
#include "scene/tree_record.h"

#include <cstdint>
#include <vector>

namespace urbis {

/// The trees' (bark, leaves) material pairs, in treeMaterials' order: a record's material is the
/// first of its pair (TreeMaterial), at firstMaterial + 2 * pair.
enum class TreeLeaves : uint32_t { Dark, Summer, Light, Needles, Autumn, Count };

/// The materials of TreeLeaves, two per pair: the bark, then the leaves (summer's broadleaves at
/// 0.8, 1 and 1.2 times leafAlbedo).
std::vector<Material> treeMaterials(const TreeOptions& options);

/// The record of `tree` (model metres: x east, y north; world x, -z), its foot on the ground plane
/// (y = 0). `key` seeds its variation (untagged height and crown within +-sizeVariation, the leaf
/// shade) and its crown's noise. Untagged: the crown's diameter 0.6 (broadleaf) or 0.35 (conifer)
/// of the height; the trunk's radius 1.8 % of the height (a 10 m tree: 18 cm), from `circumference`
/// where tagged; the crown starts at 35 % (broadleaf) or 15 % (conifer) of the height.
TreeRecord treeRecordOf(const Tree& tree, uint32_t key, const TreeOptions& options, uint32_t object, uint32_t firstMaterial);

} // namespace urbis
