#include "citygen/city_trees.h"

#include "math/hash.h"
#include "nature/forest_records.h"
#include "nature/tree_mesher.h"
#include "nature/tree_placement.h"
#include "nature/tree_records.h"

#include <algorithm>

namespace urbis {

void addCityTrees(const CityModel& city, const CityMeshOptions& options, uint32_t firstObject, CityMesh& out) {
    const std::vector<Tree> trees = placeTrees(city, options.trees, out.dropped);
    constexpr uint32_t kLastObject = (1u << 24) - 1;
    const uint32_t firstMaterial = uint32_t(out.materials.size());
    const uint32_t forestObject = std::min<uint64_t>(uint64_t(firstObject) + trees.size(), kLastObject);
    out.forests = outerForestRecords(city, options.trees, forestObject, firstMaterial);
    uint64_t forestTrees = 0;
    for (const ForestRecord& forest : out.forests) forestTrees += forestTreeCount(forest);
    out.streetCounts["trees"] = trees.size() + forestTrees;
    if (trees.empty() && out.forests.empty()) return;
    for (const Material& m : treeMaterials(options.trees)) out.materials.push_back(m);
    const bool twin = options.geometry.trees != Representation::Procedural;
    size_t triangles = 0;
    for (size_t i = 0; i < trees.size(); ++i) {
        const uint32_t object = std::min<uint64_t>(uint64_t(firstObject) + i, kLastObject);
        const TreeRecord r = treeRecordOf(trees[i], hash3(options.trees.seed, 0x73eeu, uint32_t(i)), options.trees, object,
                                          firstMaterial);
        if (twin) triangles += meshTree(r, out.mesh);
        else out.trees.push_back(r);
    }
    if (twin) out.trianglesByKind["trees"] += triangles;
}

} // namespace urbis
