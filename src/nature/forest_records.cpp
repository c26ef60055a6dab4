#include "nature/forest_records.h"

#include "nature/tree_placement.h"
#include "nature/tree_records.h"
#include "scene/forest_cells.h"
#include "scene/tree_shape.h"

#include <algorithm>
#include <cmath>

namespace urbis {

namespace {

/// How far (metres) the box of the largest tree `options` can grow reaches from its foot sideways
/// (x) and up (y): both variations at their top, which makes the box largest (height, crown, noise
/// and trunk all grow with them), for a broadleaf and a conifer.
Vec2f largestTreeReach(const TreeOptions& options) {
    Vec2f reach{0.0f, 0.0f};
    const float most = 1.0f + options.sizeVariation;
    for (const bool conifer : {false, true}) {
        TreeSizes sizes;
        sizes.height = options.defaultHeight * most;
        sizes.heightTagged = sizes.crownTagged = true;
        sizes.crownDiameter = std::min(sizes.height, 150.0f) * (conifer ? 0.35f : 0.6f) * most;
        sizes.conifer = conifer;
        HashStream rng{0};
        const Bounds3f box = treeLocalBounds(treeShapeOf(grownTreeRecord({}, sizes, treeStyleOf(options), rng, 0, 0)));
        reach = {std::max({reach.x, box.hi.x, box.hi.z, -box.lo.x, -box.lo.z}), std::max(reach.y, box.hi.y)};
    }
    return reach;
}

} // namespace

ForestRecord forestRecordOf(float x0, float z0, float x1, float z1, const TreeOptions& options, uint32_t object,
                            uint32_t firstMaterial) {
    ForestRecord f;
    f.x0 = x0, f.z0 = z0, f.x1 = x1, f.z1 = z1;
    f.cell = options.outerForestCell;
    f.probability = std::min(1.0f, options.outerForestDensity * f.cell * f.cell / 10000.0f);
    // A percent and a centimetre more than the largest tree, for the rounding of world coordinates.
    const Vec2f reach = largestTreeReach(options);
    f.reach = reach.x * 1.01f + 0.01f;
    f.top = reach.y * 1.01f + 0.01f;
    f.neighbours = int32_t(std::floor(f.reach / f.cell + 0.01f)) + 1;
    f.height = options.defaultHeight;
    f.coniferShare = options.coniferShare;
    f.style = treeStyleOf(options);
    f.seed = hash2(options.seed, 0xf0e57u);
    f.object = object;
    f.material = firstMaterial;
    f.autumn = options.season == "autumn";
    return f;
}

std::vector<ForestRecord> outerForestRecords(const CityModel& city, const TreeOptions& options, uint32_t object,
                                             uint32_t firstMaterial) {
    if (!options.enabled || !(options.outerForest > 0.0f)) return {};
    Vec2d lo{INFINITY, INFINITY}, hi{-INFINITY, -INFINITY};
    const auto extend = [&](Vec2d p) {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    };
    double widest = 0.0;
    for (const Building& b : city.buildings)
        for (Vec2d p : b.footprint.outer) extend(p);
    for (const Area& a : city.areas)
        for (Vec2d p : a.polygon.outer) extend(p);
    for (const Road& r : city.roads) {
        widest = std::max(widest, 0.5 * r.width);
        for (Vec2d p : r.centerline) extend(p);
    }
    if (!(lo.x <= hi.x)) return {};
    // The city's extent in world metres (x east, z south), grown so that no road's sidewalk reaches a tree.
    const double margin = widest + kTreeSidewalkAllowance + options.clearance;
    const float cx0 = float(lo.x - margin), cx1 = float(hi.x + margin), cz0 = float(-hi.y - margin), cz1 = float(-lo.y + margin);
    const float w = options.outerForest;
    return {forestRecordOf(cx0 - w, cz0 - w, cx1 + w, cz0, options, object, firstMaterial),
            forestRecordOf(cx0 - w, cz1, cx1 + w, cz1 + w, options, object, firstMaterial),
            forestRecordOf(cx0 - w, cz0, cx0, cz1, options, object, firstMaterial),
            forestRecordOf(cx1, cz0, cx1 + w, cz1, options, object, firstMaterial)};
}

uint64_t forestTreeCount(const ForestRecord& forest) {
    const int32_t i0 = int32_t(std::floor(forest.x0 / forest.cell)), i1 = int32_t(std::floor(forest.x1 / forest.cell));
    const int32_t k0 = int32_t(std::floor(forest.z0 / forest.cell)), k1 = int32_t(std::floor(forest.z1 / forest.cell));
    uint64_t count = 0;
    for (int32_t k = k0; k <= k1; ++k)
        for (int32_t i = i0; i <= i1; ++i) {
            HashStream rng;
            float x, z;
            count += forestFoot(forest, i, k, rng, x, z);
        }
    return count;
}

} // namespace urbis
