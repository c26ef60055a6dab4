#include "nature/tree_records.h"

#include "math/constants.h"
#include "math/hash.h"

#include <algorithm>

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

TreeRecord treeRecordOf(const Tree& tree, uint32_t key, const TreeOptions& options, uint32_t object, uint32_t firstMaterial) {
    HashStream rng{key};
    const bool conifer = tree.leafType == LeafType::Needleleaved;
    const auto varied = [&](float v, bool tagged) {
        const float u = rng.uniform(-options.sizeVariation, options.sizeVariation);
        return tagged ? v : v * (1.0f + u);
    };
    TreeRecord r;
    r.base = {float(tree.position.x), 0.0f, float(-tree.position.y)};
    r.height = std::clamp(varied(tree.height, tree.heightTagged), 1.0f, 150.0f);
    const float diameter = tree.crownTagged ? tree.crownDiameter : r.height * (conifer ? 0.35f : 0.6f);
    r.crownRadius = std::clamp(0.5f * varied(diameter, tree.crownTagged), 0.3f, 40.0f);
    r.crownBase = r.height * (conifer ? 0.15f : 0.35f);
    // A broadleaf crown's half height must not be less than a tenth of its radius (a flat disc would
    // make the ellipsoid's scale, and so the steps, tiny).
    r.crownBase = std::min(r.crownBase, r.height - 0.2f * r.crownRadius);
    const float girthRadius = tree.circumference > 0.0f ? tree.circumference / (2.0f * kPi) : 0.018f * r.height;
    r.trunkRadius = std::clamp(girthRadius, 0.03f, 0.5f * r.crownRadius);
    r.roughness = options.roughness * r.crownRadius;
    r.frequency = options.lumps / r.crownRadius;
    r.seed = rng.next();
    r.object = object;
    r.shape = conifer ? TreeShape::Conifer : TreeShape::Broadleaf;
    const bool autumn = options.season == "autumn" && tree.leafCycle != LeafCycle::Evergreen;
    const TreeLeaves leaves = conifer  ? TreeLeaves::Needles
                              : autumn ? TreeLeaves::Autumn
                                       : TreeLeaves(rng.next() % 3u);
    r.material = firstMaterial + 2u * uint32_t(leaves);
    return r;
}

} // namespace urbis
