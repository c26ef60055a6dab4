// Generated city: heights, levels, footprint shapes, uses and roofs.
#include "layout/city_layout.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

using namespace urbis;

namespace {

CityModel city(uint64_t n, float lo = 8.0f, float hi = 120.0f) {
    LayoutParams p;
    p.buildings = n;
    p.minBuildingHeight = lo;
    p.maxBuildingHeight = hi;
    return generateCity(p);
}

Vec2d centroidOf(const Ring& r) {
    Vec2d c;
    for (const Vec2d& p : r) c = {c.x + p.x, c.y + p.y};
    return {c.x / static_cast<double>(r.size()), c.y / static_cast<double>(r.size())};
}

// Names a footprint's shape from its geometry alone: a hole makes a courtyard; among
// rectilinear rings of 8 vertices, a U has its two reflex corners next to each other.
std::string shapeOf(const Polygon& p) {
    if (!p.holes.empty()) return "courtyard";
    const Ring& r = p.outer;
    const size_t n = r.size();
    std::vector<size_t> reflex;
    for (size_t i = 0; i < n; ++i) {
        const Vec2d &a = r[(i + n - 1) % n], &b = r[i], &c = r[(i + 1) % n];
        if ((b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x) < 0) reflex.push_back(i);
    }
    if (n == 4 && reflex.empty()) return "rectangle";
    if (n == 6 && reflex.size() == 1) return "L";
    if (n == 8 && reflex.size() == 2) {
        size_t d = reflex[1] - reflex[0];
        return d == 1 || d == n - 1 ? "U" : "T";
    }
    return "other";
}

} // namespace

TEST(LayoutStyle, HeightsInRangeAndTallerInTheCentre) {
    for (auto [lo, hi] : {std::pair{8.0f, 120.0f}, std::pair{3.0f, 300.0f}, std::pair{20.0f, 25.0f}}) {
        CityModel c = city(8000, lo, hi);
        std::vector<std::pair<double, float>> byDistance;
        for (const Building& b : c.buildings) {
            EXPECT_GE(b.height, lo);
            EXPECT_LE(b.height, hi);
            Vec2d m = centroidOf(b.footprint.outer);
            byDistance.push_back({std::hypot(m.x, m.y), b.height});
        }
        std::sort(byDistance.begin(), byDistance.end());
        const size_t q = byDistance.size() / 4;
        double inner = 0, outer = 0;
        for (size_t i = 0; i < q; ++i) {
            inner += byDistance[i].second;
            outer += byDistance[byDistance.size() - 1 - i].second;
        }
        EXPECT_GT(inner, outer * (hi / lo > 2 ? 2.0 : 1.05)) << "range " << lo << "-" << hi << " m";
    }
}

TEST(LayoutStyle, LevelsFollowTheWallHeight) {
    for (const Building& b : city(2000).buildings) {
        EXPECT_EQ(b.heightSource, HeightSource::Levels);
        EXPECT_GE(b.levels, 1);
        EXPECT_LE(std::abs((b.height - b.roofHeight) / 3.2f - static_cast<float>(b.levels)), 0.5f + 1e-4f)
            << "height " << b.height << " roof " << b.roofHeight << " levels " << b.levels;
        EXPECT_GE(b.roofHeight, 0.0f);
        EXPECT_LT(b.roofHeight, b.height);
    }
}

TEST(LayoutStyle, EveryShapeAppears) {
    std::map<std::string, size_t> count;
    for (const Building& b : city(5000).buildings) ++count[shapeOf(b.footprint)];
    for (const char* s : {"rectangle", "L", "T", "U", "courtyard"}) EXPECT_GT(count[s], 10u) << s;
    EXPECT_EQ(count["other"], 0u);
}

TEST(LayoutStyle, UsesAndRoofsByDistrict) {
    CityModel c = city(8000);
    std::map<BuildingType, size_t> types;
    std::map<RoofShape, size_t> roofs;
    std::set<uint32_t> seeds;
    std::map<std::string, size_t> roofedShapes;
    for (const Building& b : c.buildings) {
        ++types[b.type];
        ++roofs[b.roofShape];
        seeds.insert(b.seed);
        if (b.roofShape != RoofShape::Flat) {
            EXPECT_EQ(b.type, BuildingType::House);
            EXPECT_GT(b.roofHeight, 0.0f);
            // Only rectangles take their street's direction: L-shaped houses get a gable per wing.
            const std::string shape = shapeOf(b.footprint);
            if (shape == "rectangle") EXPECT_GE(b.roofDirection, 0.0f);
            else EXPECT_LT(b.roofDirection, 0.0f) << shape;
            ++roofedShapes[shape];
        }
    }
    for (BuildingType t : {BuildingType::Office, BuildingType::Commercial, BuildingType::Retail,
                           BuildingType::Apartments, BuildingType::Residential, BuildingType::House})
        EXPECT_GT(types[t], 0u) << static_cast<int>(t);
    EXPECT_GT(roofs[RoofShape::Flat], c.buildings.size() / 2) << "most roofs are flat";
    EXPECT_GT(roofs[RoofShape::Gabled], 0u);
    EXPECT_GT(roofs[RoofShape::Hipped], 0u);
    EXPECT_GT(roofedShapes["rectangle"], 0u);
    EXPECT_GT(roofedShapes["L"], 0u);
    EXPECT_GT(seeds.size(), c.buildings.size() * 99 / 100) << "per-building seeds are hashes";
    // Buildings come from the centre outward: offices cluster in the first tenth, houses in the last.
    const size_t n = c.buildings.size(), tenth = n / 10;
    auto countOf = [&](BuildingType t, size_t from) {
        return std::count_if(c.buildings.begin() + static_cast<long>(from),
                             c.buildings.begin() + static_cast<long>(from + tenth),
                             [t](const Building& b) { return b.type == t; });
    };
    EXPECT_GT(countOf(BuildingType::Office, 0), 5 * countOf(BuildingType::Office, n - tenth) + 20);
    EXPECT_GT(countOf(BuildingType::House, n - tenth), 5 * countOf(BuildingType::House, 0) + 20);
}
