#include "nature/tree_records.h"

namespace urbis {

std::vector<Material> treeMaterials(const TreeOptions& options) {
    std::vector<Material> out;
    const auto pair = [&](Vec3f leaves) {
        out.push_back(Material{options.barkAlbedo});
        out.push_back(Material{leaves});
    };
    pair(options.leafAlbedo * 0.8f);
    pair(options.leafAlbedo);
    pair(vmin(options.leafAlbedo * 1.2f, Vec3f{0.95f, 0.95f, 0.95f}));
    pair(options.needleAlbedo);
    pair(options.autumnAlbedo);
    return out;
}

TreeStyle treeStyleOf(const TreeOptions& options) { return {options.sizeVariation, options.roughness, options.lumps}; }

TreeRecord treeRecordOf(const Tree& tree, uint32_t key, const TreeOptions& options, uint32_t object, uint32_t firstMaterial) {
    TreeSizes sizes;
    sizes.height = tree.height;
    sizes.heightTagged = tree.heightTagged;
    sizes.crownDiameter = tree.crownDiameter;
    sizes.crownTagged = tree.crownTagged;
    sizes.circumference = tree.circumference;
    sizes.conifer = tree.leafType == LeafType::Needleleaved;
    sizes.autumn = options.season == "autumn" && tree.leafCycle != LeafCycle::Evergreen;
    HashStream rng{key};
    return grownTreeRecord({float(tree.position.x), 0.0f, float(-tree.position.y)}, sizes, treeStyleOf(options), rng, object,
                           firstMaterial);
}

} // namespace urbis
