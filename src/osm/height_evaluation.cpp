#include "osm/height_evaluation.h"

#include "math/quantile.h"
#include "osm/building_tags.h"
#include "osm/height_estimate.h"

#include <cmath>

namespace urbis {

namespace {

constexpr uint32_t kHiddenSalt = 0x68e31da4u; // apart from the estimate's own draws

} // namespace

HeightError evaluateHeightEstimate(const CityModel& city, const ImportOptions& options) {
    CityModel hidden = city;
    std::vector<float> truth(city.buildings.size(), -1.0f); // -1: not hidden
    for (size_t i = 0; i < city.buildings.size(); ++i) {
        Building& b = hidden.buildings[i];
        if (!isTagged(b.heightSource) || (objectSeed(options.seed ^ kHiddenSalt, b.osmId) & 1u) == 0) continue;
        truth[i] = b.height - b.minHeight;
        b.heightSource = HeightSource::TypeTable; // what buildingFromTags gives a building without tags
        b.levels = -1;
    }
    estimateHeights(hidden, options);
    std::vector<double> errors;
    for (size_t i = 0; i < truth.size(); ++i)
        if (truth[i] >= 0.0f) {
            const Building& b = hidden.buildings[i];
            errors.push_back(std::abs(double(b.height - b.minHeight) - double(truth[i])));
        }
    if (errors.empty()) return {};
    return {errors.size(), quantile(errors, 0.5), quantile(errors, 0.9)};
}

} // namespace urbis
