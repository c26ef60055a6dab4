#include "osm/building_palette.h"

#include "math/hash.h"
#include "osm/colour_table.h"

#include <algorithm>
#include <array>
#include <span>

namespace urbis {

namespace {

// sRGB values, muted as weathered surfaces are; converted to linear when drawn.
using Swatches = std::span<const uint32_t>;

constexpr uint32_t kFlatRoofs[] = {0x8a8680, 0x4a4a4a, 0x5c5a57, 0x9a9792, 0xc8c8c2, 0xa8a6a0, 0x6e6c68};
constexpr uint32_t kDomes[] = {0x6f9a86, 0x7fa894, 0x6e7378, 0x4d5257};
constexpr uint32_t kHallRoofs[] = {0x8a9094, 0x7a8086, 0x9ea3a6, 0x6b7075, 0x8f8a80};

struct RegionSwatches {
    PaletteRegion region;
    Swatches pitchedRoofs, homeWalls;
};

constexpr uint32_t kCentralRoofs[] = {0x8c4a36, 0x7b3f2f, 0x9a5a42, 0x6a3c30, 0x4c4c4e, 0x3c3e42, 0x5a4036};
constexpr uint32_t kCentralWalls[] = {0xe9e4d8, 0xe8dcc0, 0xdcc79c, 0xcfb58a, 0xd9d4cc, 0xc4b8a8, 0x9c5c46, 0xe2d2c2};
constexpr uint32_t kBritishRoofs[] = {0x4b5058, 0x555a61, 0x3e4248, 0x5c6066, 0x8a5040, 0x7a4536};
constexpr uint32_t kBritishWalls[] = {0x9a5a44, 0xb9a27c, 0xa88e6a, 0xe6e0d4, 0xd6cdb8, 0xcfc6b4, 0xbcb8b0, 0x8a4e3c};
constexpr uint32_t kSouthernRoofs[] = {0xa65e40, 0xb06c4a, 0x9a5538, 0x8e5a44, 0xb8805c};
constexpr uint32_t kSouthernWalls[] = {0xefe8da, 0xe8d2a8, 0xdcb888, 0xe0c2a2, 0xf0ebe2, 0xcfa37a};
constexpr uint32_t kEasternRoofs[] = {0x5f7a66, 0x687076, 0x7a4a3a, 0x4f5a52, 0x8a8e92, 0x5a6470};
constexpr uint32_t kEasternWalls[] = {0xe8d39c, 0xe6c8b4, 0xece8de, 0xd8c8a8, 0xb8b6ae, 0xc9d0c8};
constexpr uint32_t kAmericanRoofs[] = {0x4a4a4a, 0x5b5650, 0x6b6259, 0x3d3b3a, 0x7a6e62, 0x55504a};
constexpr uint32_t kAmericanWalls[] = {0x8e4f3c, 0xa0705a, 0xd8d4c8, 0xc4bca8, 0xa8aaa8, 0xb8ab94, 0xe0dcd2, 0xc8c8c4};
constexpr uint32_t kOtherRoofs[] = {0x6b5a50, 0x4c4c4e, 0x7b4a3a, 0x5a5a5c};
constexpr uint32_t kOtherWalls[] = {0xddd6c8, 0xcfc8ba, 0xbdb8ae, 0xd8cdb4, 0xa8a49c};

constexpr RegionSwatches kRegions[] = {
    {PaletteRegion::CentralEurope, kCentralRoofs, kCentralWalls},
    {PaletteRegion::BritishIsles, kBritishRoofs, kBritishWalls},
    {PaletteRegion::SouthernEurope, kSouthernRoofs, kSouthernWalls},
    {PaletteRegion::EasternEurope, kEasternRoofs, kEasternWalls},
    {PaletteRegion::NorthAmerica, kAmericanRoofs, kAmericanWalls},
    {PaletteRegion::Other, kOtherRoofs, kOtherWalls},
};

constexpr uint32_t kPublicWalls[] = {0xc8c4bc, 0xb0aca6, 0xa9b0b6, 0xd8d2c6, 0x9a9892, 0xcfc6b2};
constexpr uint32_t kChurchWalls[] = {0xc8bca4, 0xb5a88e, 0xd6ccb8, 0x9c8f7a, 0x8a5240};
constexpr uint32_t kHallWalls[] = {0xa8aaa8, 0x8e9498, 0xb8b4aa, 0x9aa0a4, 0xc4c2ba};

const RegionSwatches& swatchesOf(PaletteRegion region) {
    for (const RegionSwatches& s : kRegions)
        if (s.region == region) return s;
    return kRegions[std::size(kRegions) - 1];
}

/// Halls, sheds, garages and bare roofs: clad in metal, fibre cement or concrete.
bool isHall(BuildingType type) {
    using T = BuildingType;
    return type == T::Industrial || type == T::Warehouse || type == T::Garage || type == T::Shed || type == T::Roof;
}

bool isPublic(BuildingType type) {
    using T = BuildingType;
    return type == T::Commercial || type == T::Retail || type == T::Office || type == T::Civic ||
           type == T::School || type == T::Hospital;
}

/// One swatch and a brightness step drawn from `stream`: in steps, so that a city keeps a
/// small material table (one material per distinct colour).
Rgb draw(Swatches swatches, uint32_t seed, uint32_t stream) {
    HashStream rng{hash2(seed, stream)};
    const Rgb c = fromSrgbHex(swatches[rng.next() % swatches.size()]);
    const float k = 0.9f + 0.05f * float(rng.next() % 5);
    return {std::min(1.0f, c.r * k), std::min(1.0f, c.g * k), std::min(1.0f, c.b * k)};
}

constexpr uint32_t kRoofStream = 0x526f6f66u; // "Roof"
constexpr uint32_t kWallStream = 0x57616c6cu; // "Wall"
constexpr uint32_t kUseStream = 0x55736521u;  // "Use!"

} // namespace

PaletteRegion paletteRegionOf(const GeoOrigin& origin) {
    if (!origin.valid) return PaletteRegion::Other;
    const double lon = origin.lon, lat = origin.lat;
    if (lon >= -170.0 && lon <= -50.0 && lat >= 15.0 && lat <= 75.0) return PaletteRegion::NorthAmerica;
    if (lon < -25.0 || lon > 60.0 || lat < 34.0 || lat > 72.0) return PaletteRegion::Other;
    if (lon >= -11.0 && lon <= 2.0 && lat >= 49.8) return PaletteRegion::BritishIsles;
    if (lat < 45.0) return PaletteRegion::SouthernEurope;
    if (lon > 24.0) return PaletteRegion::EasternEurope;
    return PaletteRegion::CentralEurope;
}

Rgb paletteRoofColour(PaletteRegion region, const Building& b) {
    Swatches swatches = swatchesOf(region).pitchedRoofs;
    switch (b.roofShape) {
    case RoofShape::Flat:
    case RoofShape::Unknown: swatches = kFlatRoofs; break;
    case RoofShape::Dome:
    case RoofShape::Onion: swatches = kDomes; break;
    default:
        if (isHall(b.type)) swatches = kHallRoofs;
        break;
    }
    return draw(swatches, b.seed, kRoofStream);
}

Rgb paletteWallColour(PaletteRegion region, const Building& b) {
    Swatches swatches = swatchesOf(region).homeWalls;
    if (isHall(b.type)) swatches = kHallWalls;
    else if (isPublic(b.type)) swatches = kPublicWalls;
    else if (b.type == BuildingType::Religious) swatches = kChurchWalls;
    // building=yes is an office block as often as a home: half of them get the public walls.
    else if (b.type == BuildingType::Generic && hashToUnit(hash2(b.seed, kUseStream)) < 0.5f) swatches = kPublicWalls;
    return draw(swatches, b.seed, kWallStream);
}

void paintUntaggedBuildings(CityModel& city) {
    const PaletteRegion region = paletteRegionOf(city.origin);
    for (Building& b : city.buildings) {
        if (!b.wallColourTagged) b.wallColour = paletteWallColour(region, b);
        if (!b.roofColourTagged) b.roofColour = paletteRoofColour(region, b);
    }
}

} // namespace urbis
