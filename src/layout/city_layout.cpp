#include "layout/city_layout.h"

#include "layout/arterial_junctions.h"
#include "layout/bridges.h"
#include "layout/building_style.h"
#include "layout/footprint_shapes.h"
#include "layout/lots.h"
#include "layout/parks.h"
#include "layout/pedestrian_crossings.h"
#include "layout/river.h"
#include "layout/street_furniture.h"
#include "layout/street_grid.h"
#include "math/hash.h"
#include "base/input_error.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

namespace urbis {

namespace {

// Ground area per building in square metres, roads included, measured on generated cities:
// it sizes the first grid and the districts.
constexpr double kAreaPerBuilding = 750.0;
constexpr float kParkChance = 0.04f;          // per block, away from the arterials and the river
constexpr float kPlazaChance = 0.05f;         // per block of the centre that is not a park
constexpr double kParkAreaPerTree = 150.0;    // m^2
constexpr double kStreetTreeSpacing = 12.0;   // m along a residential street, both sides
constexpr double kTreeFromBuildings = 0.8;    // m from the sidewalk's outer edge
constexpr double kRiverBank = 6.0;            // m (north-south) between the water and any lot
constexpr double kTreeFromRiver = 20.0;       // m (north-south): none by the water or on a bridge

// Streams of the counter-based hash, one per purpose.
enum Purpose : uint32_t { BlockLots = 1, BlockPark, ParkTrees, BuildingSeed, BlockPlaza };

void validate(const LayoutParams& p) {
    if (p.buildings == 0) throw InputError("layout: the building count must be at least 1", FailureKind::Usage);
    if (p.buildings > kMaxGeneratedBuildings)
        throw InputError("layout: at most " + std::to_string(kMaxGeneratedBuildings) + " buildings, not " +
                         std::to_string(p.buildings), FailureKind::Usage);
    if (!std::isfinite(p.minBuildingHeight) || !std::isfinite(p.maxBuildingHeight) ||
        p.minBuildingHeight <= 0.0f || p.maxBuildingHeight <= 0.0f)
        throw InputError("layout: building heights must be finite and positive", FailureKind::Usage);
    if (p.minBuildingHeight > p.maxBuildingHeight)
        throw InputError("layout: minimum building height " + std::to_string(p.minBuildingHeight) +
                         " m is above the maximum " + std::to_string(p.maxBuildingHeight) + " m",
                         FailureKind::Usage);
}

// Which blocks of a grid hold the city, and what is on them.
struct Plan {
    StreetGrid grid;
    std::vector<Lot> lots;       // one building each, in order from the centre outward
    std::vector<bool> used;      // per block, indexed as StreetGrid::roads expects
    std::vector<Rect2d> parks, plazas;
    double radius = 0;           // m, farthest corner of a used block from (0, 0)
};

double farthestCorner(const Rect2d& r) {
    return std::hypot(std::max(std::abs(r.x0), std::abs(r.x1)), std::max(std::abs(r.y0), std::abs(r.y1)));
}

// Fills the blocks of `plan.grid` nearest to the centre first until there are `target` lots;
// false if the grid is too small.
bool fill(Plan& plan, const Arterials& arterials, const River& river, uint64_t target, uint32_t seed,
          double districtRadius) {
    const int half = plan.grid.half(), n = 2 * half;
    std::vector<std::pair<double, int>> order;
    order.reserve(static_cast<size_t>(n) * static_cast<size_t>(n));
    for (int j = -half; j < half; ++j)
        for (int i = -half; i < half; ++i) {
            Vec2d c = plan.grid.blockInterior(i, j).centre();
            order.push_back({c.x * c.x + c.y * c.y, (j + half) * n + i + half});
        }
    std::sort(order.begin(), order.end());
    plan.used.assign(order.size(), false);
    std::vector<Lot> blockLots;
    for (size_t rank = 0; rank < order.size() && plan.lots.size() < target; ++rank) {
        const int index = order[rank].second, i = index % n - half, j = index / n - half;
        const Rect2d block = plan.grid.blockInterior(i, j);
        const uint32_t key = hash3(seed, static_cast<uint32_t>(i), static_cast<uint32_t>(j));
        plan.used[static_cast<size_t>(index)] = true;
        plan.radius = std::max(plan.radius, farthestCorner(block));
        const District district = districtAt(std::sqrt(order[rank].first) / districtRadius);
        if (rank > 0 && !arterials.blocks(block) && !river.near(block, kRiverBank)) {
            if (hashToUnit(hash2(key, BlockPark)) < kParkChance) {
                plan.parks.push_back(block);
                continue;
            }
            if (district == District::Centre && hashToUnit(hash2(key, BlockPlaza)) < kPlazaChance) {
                plan.plazas.push_back(block);
                continue;
            }
        }
        blockLots.clear();
        subdivideBlock(block, district, hash2(key, BlockLots), blockLots);
        for (const Lot& lot : blockLots)
            if (plan.lots.size() < target && !arterials.blocks(lot.bounds()) && !river.near(lot.bounds(), kRiverBank))
                plan.lots.push_back(lot);
    }
    return plan.lots.size() == target;
}

std::vector<Building> buildingsOn(const std::vector<Lot>& lots, const LayoutParams& p, double radius) {
    std::vector<Building> out(lots.size());
    const HeightRange range{p.minBuildingHeight, p.maxBuildingHeight};
    tbb::parallel_for(tbb::blocked_range<size_t>(0, lots.size(), 2048), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t i = r.begin(); i != r.end(); ++i) {
            Building& b = out[i];
            b.seed = hash3(p.seed, BuildingSeed, static_cast<uint32_t>(i));
            HashStream rng{b.seed};
            Footprint f = makeFootprint(lots[i], rng);
            b.footprint = std::move(f.polygon);
            Vec2d c = lots[i].bounds().centre();
            styleBuilding(b, lots[i], f.shape, std::hypot(c.x, c.y) / radius, range, rng);
        }
    });
    return out;
}

// Trees along residential streets, on the sidewalks, leaving out those that would stand on a
// crossing road, by the water or on a bridge.
void plantStreetTrees(CityModel& city, size_t gridRoads, const StreetGrid& grid, const Arterials& arterials,
                      const River& river) {
    for (size_t r = 0; r < gridRoads; ++r) {
        const Road& road = city.roads[r];
        if (road.highway != HighwayClass::Residential) continue;
        const bool northSouth = road.centerline[0].x == road.centerline[1].x;
        auto offRoads = [&](Vec2d p) {
            return !(northSouth ? grid.onEastWestRoad(p) : grid.onNorthSouthRoad(p)) && arterials.corridorsAt(p) == 0;
        };
        const double offset = 0.5 * road.width + road.sidewalkLeftWidth - kTreeFromBuildings;
        for (Vec2d p : pointsBeside(road, kStreetTreeSpacing, offset)) {
            if (!offRoads(p) || river.distance(p) < kTreeFromRiver) continue;
            Tree tree;
            tree.position = p;
            tree.height = 7.0f;
            tree.crownDiameter = 4.0f;
            city.trees.push_back(tree);
        }
    }
}

} // namespace

CityModel generateCity(const LayoutParams& params) {
    validate(params);
    const double estimatedRadius =
        std::sqrt(static_cast<double>(params.buildings) * kAreaPerBuilding / std::numbers::pi);
    const River river = River::generate(params.seed);
    const Arterials arterials = Arterials::generate(params.seed, estimatedRadius, river);
    int half = static_cast<int>(estimatedRadius / 60.0) + 2;
    Plan plan{StreetGrid(params.seed, half), {}, {}, {}, {}, 0};
    while (!fill(plan, arterials, river, params.buildings, params.seed, estimatedRadius)) {
        half = half * 3 / 2 + 2;
        plan = Plan{StreetGrid(params.seed, half), {}, {}, {}, {}, 0};
    }

    CityModel city;
    city.source = "generated";
    city.buildings = buildingsOn(plan.lots, params, plan.radius);
    std::vector<Road> arterialRoads = arterials.roads(plan.radius);
    city.roads = plan.grid.roads(plan.used, riverGridFilter(plan.grid, river, arterialRoads, params.seed));
    joinArterials(plan.grid, arterials, city.roads, arterialRoads);
    const size_t gridRoads = city.roads.size();
    for (Road& r : arterialRoads) city.roads.push_back(std::move(r));
    plantStreetTrees(city, gridRoads, plan.grid, arterials, river);
    city.crossings = placeCrossings(city.roads, params.seed, river);
    splitBridges(city.roads, river);
    for (size_t k = 0; k < plan.parks.size(); ++k)
        layOutPark(plan.parks[k], hash3(params.seed, ParkTrees, static_cast<uint32_t>(k)), kParkAreaPerTree, city);
    for (size_t k = 0; k < plan.plazas.size(); ++k)
        city.areas.push_back(plazaOn(plan.plazas[k], hash3(params.seed, BlockPlaza, static_cast<uint32_t>(k))));
    if (river.reaches(plan.radius)) {
        Area water;
        water.kind = AreaKind::Water;
        water.polygon.outer = river.polygon(-plan.radius, plan.radius);
        water.flowLine = river.flowLine(-plan.radius, plan.radius);   // on a terrain it falls along it
        city.areas.push_back(std::move(water));
    }
    return city;
}

} // namespace urbis
