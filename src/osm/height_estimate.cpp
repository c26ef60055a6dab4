#include "osm/height_estimate.h"

#include "math/quantile.h"
#include "model/polygon_ops.h"
#include "osm/building_tags.h"
#include "model/cell_grid.h"
#include "osm/height_table.h"

#include <algorithm>
#include <optional>

namespace urbis {

namespace {

// Salts keep the per-building draws apart. The range's is fixed so that a scene rendered with
// --building-height-range and a seed keeps its heights from one version to the next.
constexpr uint32_t kRangeSalt = 0x5bd1e995u, kTableSalt = 0x27d4eb2fu;

float uniform(uint32_t seed, uint32_t salt, int64_t osmId) {
    return float(objectSeed(seed ^ salt, osmId)) * 0x1p-32f;
}

/// Tagged buildings by the grid cell of their centroid.
class TaggedNeighbours {
public:
    TaggedNeighbours(const std::vector<Building>& buildings, const std::vector<Vec2d>& centroids)
        : buildings_(buildings), centroids_(centroids) {
        for (uint32_t i = 0; i < buildings.size(); ++i)
            if (isTagged(buildings[i].heightSource)) grid_.insert(i, {centroids[i], centroids[i]});
    }

    /// Median height above base of the tagged buildings of `type` near `centre`: within the
    /// radius, else twice the radius (which beat the table on the extracts, docs/heights.md);
    /// nullopt when both hold fewer than kMinHeightNeighbours.
    std::optional<float> median(Vec2d centre, BuildingType type) const {
        for (const double r : {kHeightNeighbourRadius, 2.0 * kHeightNeighbourRadius})
            if (const std::optional<float> m = medianWithin(centre, type, r)) return m;
        return std::nullopt;
    }

private:
    std::optional<float> medianWithin(Vec2d centre, BuildingType type, double r) const {
        std::vector<float> heights;
        grid_.query({Vec2d{centre.x - r, centre.y - r}, Vec2d{centre.x + r, centre.y + r}}, [&](uint32_t j) {
            const Vec2d d{centroids_[j].x - centre.x, centroids_[j].y - centre.y};
            if (buildings_[j].type == type && d.x * d.x + d.y * d.y <= r * r)
                heights.push_back(buildings_[j].height - buildings_[j].minHeight);
        });
        if (heights.size() < kMinHeightNeighbours) return std::nullopt;
        return float(quantile(heights, 0.5));
    }

    const std::vector<Building>& buildings_;
    const std::vector<Vec2d>& centroids_;
    CellGrid grid_{kHeightNeighbourRadius};
};

} // namespace

void estimateHeights(CityModel& city, const ImportOptions& options) {
    std::vector<Vec2d> centroids(city.buildings.size());
    std::transform(city.buildings.begin(), city.buildings.end(), centroids.begin(),
                   [](const Building& b) { return centroid(b.footprint.outer); });
    // Only tagged buildings are neighbours and the loop changes only untagged ones, so the
    // index may read the buildings while they are estimated.
    const TaggedNeighbours neighbours(city.buildings, centroids);
    const Region region = city.origin.valid ? regionOf(city.origin.lat, city.origin.lon) : Region::Other;
    for (size_t i = 0; i < city.buildings.size(); ++i) {
        Building& b = city.buildings[i];
        if (isTagged(b.heightSource)) continue;
        float height = 0.0f;
        if (const auto& range = options.untaggedHeightRange) {
            height = (*range)[0] + uniform(options.seed, kRangeSalt, b.osmId) * ((*range)[1] - (*range)[0]);
            b.heightSource = HeightSource::Range;
        } else if (const std::optional<float> median = neighbours.median(centroids[i], b.type)) {
            height = *median;
            b.heightSource = HeightSource::NearbyMedian;
        } else {
            const HeightSpan span = typicalHeight(b.type, region);
            height = span.min + uniform(options.seed, kTableSalt, b.osmId) * (span.max - span.min);
            b.heightSource = HeightSource::TypeTable;
        }
        b.height = b.minHeight + std::max(height, b.roofHeight + options.metresPerLevel);
    }
}

} // namespace urbis
