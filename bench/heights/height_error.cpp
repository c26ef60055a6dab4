// urbis_height_error FILE...: how well untagged heights are estimated on real extracts, as a
// markdown table (docs/heights.md). For each file, half of the tagged buildings are hidden
// and estimated from the rest, by the estimate and by the old seeded 20-100 m rule.
#include "base/input_error.h"
#include "osm/height_estimate.h"
#include "osm/height_evaluation.h"
#include "osm/osm_import.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <numeric>
#include <string>

using namespace urbis;

namespace {

/// The seeded range every untagged building got before heights were estimated.
ImportOptions oldRule() {
    ImportOptions o;
    o.untaggedHeightRange = {{20.0f, 100.0f}};
    return o;
}

double meanHeight(const CityModel& city) {
    const double sum = std::accumulate(city.buildings.begin(), city.buildings.end(), 0.0,
                                       [](double s, const Building& b) { return s + b.height; });
    return sum / double(city.buildings.size());
}

/// "median / p90", or a dash where no building was hidden (a file with one tagged building).
std::string errors(const HeightError& e) {
    if (e.hidden == 0) return "-";
    char text[64];
    std::snprintf(text, sizeof text, "%.1f / %.1f", e.median, e.p90);
    return text;
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s FILE.osm[.pbf|.bz2]...\n", argv[0]);
        return 2;
    }
    std::printf("| extract | buildings | tagged | untagged: nearby / table | hidden | estimate median / p90 (m) "
                "| old 20-100 m median / p90 (m) | mean height old -> new (m) |\n"
                "|---|---:|---:|---:|---:|---:|---:|---:|\n");
    for (int i = 1; i < argc; ++i) {
        try {
            const CityModel city = importOsm(argv[i], {});
            CityModel old = city;
            estimateHeights(old, oldRule());
            const auto count = [&city](auto predicate) {
                return size_t(std::count_if(city.buildings.begin(), city.buildings.end(), predicate));
            };
            const size_t tagged = count([](const Building& b) { return isTagged(b.heightSource); });
            const size_t nearby = count([](const Building& b) { return b.heightSource == HeightSource::NearbyMedian; });
            const HeightError now = evaluateHeightEstimate(city, {}), before = evaluateHeightEstimate(city, oldRule());
            std::printf("| %s | %zu | %zu | %zu / %zu | %zu | %s | %s | %.1f -> %.1f |\n",
                        std::filesystem::path(argv[i]).filename().c_str(), city.buildings.size(), tagged, nearby,
                        city.buildings.size() - tagged - nearby, now.hidden, errors(now).c_str(),
                        errors(before).c_str(), meanHeight(old), meanHeight(city));
        } catch (const InputError& e) {
            std::fprintf(stderr, "%s\n", e.what());
            return 1;
        }
    }
    return 0;
}
