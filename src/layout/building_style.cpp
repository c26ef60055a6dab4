#include "layout/building_style.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <utility>

namespace urbis {

namespace {

struct Use {
    BuildingType type;
    float chance;
};

// Uses per district (Centre, Middle, Outskirts); chances sum to 1.
constexpr std::array<std::array<Use, 5>, 3> kUses = {{
    {{{BuildingType::Office, 0.45f}, {BuildingType::Commercial, 0.25f}, {BuildingType::Retail, 0.10f},
      {BuildingType::Hotel, 0.05f}, {BuildingType::Apartments, 0.15f}}},
    {{{BuildingType::Apartments, 0.45f}, {BuildingType::Residential, 0.20f}, {BuildingType::Retail, 0.15f},
      {BuildingType::Commercial, 0.10f}, {BuildingType::Office, 0.10f}}},
    {{{BuildingType::House, 0.60f}, {BuildingType::Residential, 0.28f}, {BuildingType::Retail, 0.06f},
      {BuildingType::Warehouse, 0.03f}, {BuildingType::Industrial, 0.03f}}},
}};

BuildingType chooseType(District district, FootprintShape shape, HashStream& rng) {
    float u = rng.uniform();
    BuildingType type = BuildingType::Residential;
    for (const Use& use : kUses[static_cast<size_t>(district)]) {
        type = use.type;
        if (u < use.chance) break;
        u -= use.chance;
    }
    // Detached houses are simple: a T or U plan becomes a residential building.
    if (type == BuildingType::House && shape != FootprintShape::Rectangle && shape != FootprintShape::L)
        type = BuildingType::Residential;
    return type;
}

// Linear-RGB wall palettes: light stone and plaster, brick, glass-and-steel, concrete.
constexpr std::array<Rgb, 4> kPlaster = {{{0.75f, 0.70f, 0.60f}, {0.80f, 0.78f, 0.72f},
                                          {0.70f, 0.62f, 0.50f}, {0.62f, 0.66f, 0.68f}}};
constexpr std::array<Rgb, 4> kBrick = {{{0.45f, 0.18f, 0.12f}, {0.55f, 0.26f, 0.16f},
                                        {0.38f, 0.22f, 0.18f}, {0.60f, 0.45f, 0.32f}}};
constexpr std::array<Rgb, 4> kGlass = {{{0.30f, 0.38f, 0.45f}, {0.22f, 0.28f, 0.32f},
                                        {0.40f, 0.45f, 0.48f}, {0.18f, 0.24f, 0.30f}}};
constexpr std::array<Rgb, 4> kConcrete = {{{0.55f, 0.55f, 0.53f}, {0.62f, 0.60f, 0.56f},
                                           {0.48f, 0.50f, 0.52f}, {0.70f, 0.68f, 0.64f}}};
// Linear-RGB pitched-roof palette: clay tiles, slate, weathered copper.
constexpr std::array<Rgb, 4> kRoofTiles = {{{0.45f, 0.16f, 0.10f}, {0.30f, 0.12f, 0.08f},
                                            {0.18f, 0.19f, 0.21f}, {0.25f, 0.38f, 0.32f}}};

std::pair<BuildingMaterial, const std::array<Rgb, 4>*> facade(BuildingType type, HashStream& rng) {
    switch (type) {
    case BuildingType::Office: return {BuildingMaterial::Glass, &kGlass};
    case BuildingType::Commercial:
    case BuildingType::Hotel:
        return rng.uniform() < 0.5f ? std::pair{BuildingMaterial::Glass, &kGlass}
                                    : std::pair{BuildingMaterial::Concrete, &kConcrete};
    case BuildingType::Warehouse:
    case BuildingType::Industrial: return {BuildingMaterial::Concrete, &kConcrete};
    case BuildingType::Apartments:
    case BuildingType::Residential:
        return rng.uniform() < 0.5f ? std::pair{BuildingMaterial::Brick, &kBrick}
                                    : std::pair{BuildingMaterial::Plaster, &kPlaster};
    default: return {BuildingMaterial::Plaster, &kPlaster};
    }
}

Rgb pick(const std::array<Rgb, 4>& palette, HashStream& rng) {
    Rgb c = palette[rng.next() % palette.size()];
    float k = rng.uniform(0.9f, 1.1f);  // per-building brightness jitter
    return {std::min(1.0f, c.r * k), std::min(1.0f, c.g * k), std::min(1.0f, c.b * k)};
}

float heightAt(double normalisedRadius, HeightRange range, HashStream& rng) {
    // Geometric interpolation between min and max: the position in log space falls off like a
    // Gaussian of the distance, and the jitter is lognormal (sigma an eighth of the log range).
    const double falloff = std::exp(-std::pow(normalisedRadius / 0.4, 2.0));
    const double t = std::clamp(0.05 + 0.75 * falloff + 0.125 * rng.normal(), 0.0, 1.0);
    const double logMin = std::log(range.min), logMax = std::log(range.max);
    return std::clamp(static_cast<float>(std::exp(logMin + (logMax - logMin) * t)), range.min, range.max);
}

// Degrees clockwise from north of the direction the lot's front faces (toward its street).
float facingDegrees(const Lot& lot) {
    double deg = std::atan2(-lot.inward.x, -lot.inward.y) * 180.0 / std::numbers::pi;
    return static_cast<float>(deg < 0 ? deg + 360.0 : deg);
}

} // namespace

void styleBuilding(Building& b, const Lot& lot, FootprintShape shape, double normalisedRadius,
                   HeightRange range, HashStream& rng) {
    b.type = chooseType(lot.district, shape, rng);
    b.height = heightAt(normalisedRadius, range, rng);
    b.roofShape = RoofShape::Flat;
    b.roofHeight = 0.0f;
    if (b.type == BuildingType::House) {
        float u = rng.uniform();
        if (u < 0.8f) {
            b.roofShape = u < 0.45f ? RoofShape::Gabled : RoofShape::Hipped;
            b.roofHeight = std::min(0.5f * b.height, std::clamp(0.3f * b.height, 2.0f, 5.0f));
            // A rectangle's ridge follows its street; an L-shaped house, without a direction, gets a
            // ridge and a gable per wing (or a hipped roof) from its straight skeleton.
            if (shape == FootprintShape::Rectangle) b.roofDirection = facingDegrees(lot);
        }
    }
    b.levels = std::max(1, static_cast<int>(std::lround((b.height - b.roofHeight) / kStoreyHeight)));
    b.heightSource = HeightSource::Levels;
    auto [material, palette] = facade(b.type, rng);
    b.material = material;
    b.wallColour = pick(*palette, rng);
    if (b.roofShape != RoofShape::Flat) b.roofColour = pick(kRoofTiles, rng);
}

} // namespace urbis
