// Estimated heights on real extracts: half of the tagged buildings hidden and guessed back
// must stay within 20 % of the median error measured in docs/heights.md.
#include "osm/height_evaluation.h"
#include "osm/osm_import.h"

#include <gtest/gtest.h>

#include <filesystem>

using namespace urbis;

namespace {

struct Measured {
    const char* name;
    std::string path;
    double medianError; ///< m, docs/heights.md (urbis_height_error, seed 1)
};

const std::string kShared = URBIS_SHARED_DATA;

const Measured kMeasured[] = {
    {"SanFrancisco", kShared + "/sf_downtown_2023.osm.pbf", 3.0},
    {"London", kShared + "/london_city_2020.osm.pbf", 3.0},
};

/// Names the case in test output instead of dumping its bytes.
void PrintTo(const Measured& m, std::ostream* os) { *os << m.name; }

class HeightEstimateExtract : public testing::TestWithParam<Measured> {};

} // namespace

TEST_P(HeightEstimateExtract, MedianErrorStaysWithinTwentyPercentOfMeasured) {
    const Measured& m = GetParam();
    if (!std::filesystem::exists(m.path)) GTEST_SKIP() << m.path << " not found (URBIS_SHARED_DATA), skipping";
    const HeightError error = evaluateHeightEstimate(importOsm(m.path, {}), {});
    RecordProperty("median_error_m", std::to_string(error.median));
    EXPECT_GT(error.hidden, 100u);
    EXPECT_LE(error.median, 1.2 * m.medianError) << m.name << ": p90 " << error.p90 << " m";
}

INSTANTIATE_TEST_SUITE_P(RealData, HeightEstimateExtract, testing::ValuesIn(kMeasured),
                         [](const testing::TestParamInfo<Measured>& param) { return std::string(param.param.name); });
