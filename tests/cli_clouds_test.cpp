// `urbis render --clouds` end to end: the tables in the stats, a bad coverage, a bad scene file.
#include "cli_support.h"

#include "scene/cloud_layer.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>

using namespace urbis::test;

namespace {
const std::string kSmall = "render --width 48 --height 32 --spp 1 --buildings 20 ";
}

// With clouds the stats count the noise volume and the coverage tables under bytes_by_kind; without
// (the default) they hold no bytes.
TEST(CliClouds, StatsCountTheCloudTables) {
    auto dir = scratchDir("clouds_stats");
    CommandResult r = runUrbis(kSmall + "--clouds 0.4 --stats with.json --out with.png", dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto with = nlohmann::json::parse(readFile(dir / "with.json"));
    EXPECT_EQ(with["bytes_by_kind"]["cloud_noise"].get<size_t>(),
              size_t(urbis::kCloudNoiseSize) * urbis::kCloudNoiseSize * urbis::kCloudNoiseSize * sizeof(urbis::CloudNoiseTexel));
    EXPECT_EQ(with["bytes_by_kind"]["cloud_coverage"].get<size_t>(), size_t(urbis::kCloudCoverageSize) * urbis::kCloudCoverageSize * 4);
    EXPECT_NEAR(with["scene"]["clouds"]["coverage"].get<double>(), 0.4, 1e-6);
    ASSERT_EQ(runUrbis(kSmall + "--stats without.json --out without.png", dir).exitCode, 0);
    const auto without = nlohmann::json::parse(readFile(dir / "without.json"));
    EXPECT_EQ(without["bytes_by_kind"]["cloud_noise"].get<size_t>(), 0u);
}

// A coverage outside [0, 1] and an unknown cloud type: one line naming the problem, exit not 0, no image.
TEST(CliClouds, BadCoverageAndTypeAreRefused) {
    auto dir = scratchDir("clouds_bad");
    CommandResult r = runUrbis(kSmall + "--clouds 1.5 --out bad.png", dir);
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.err.find("--clouds"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "bad.png"));
    std::ofstream(dir / "clouds.json") << R"({"clouds": {"coverage": 0.5, "type": "cirrus"}})";
    CommandResult s = runUrbis(kSmall + "--scene clouds.json --out bad2.png", dir);
    EXPECT_NE(s.exitCode, 0);
    EXPECT_NE(s.err.find("clouds.type"), std::string::npos) << s.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "bad2.png"));
}
