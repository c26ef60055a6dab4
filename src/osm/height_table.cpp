#include "osm/height_table.h"

#include <array>

namespace urbis {

namespace {

struct Row {
    BuildingType type;
    Region region;
    HeightSpan span;
};

using T = BuildingType;
using R = Region;

// Storeys of about 3 m; a pitched roof adds 2-3 m. Other rows first, then regional ones.
// Checked against the medians of the tagged buildings of the extracts in docs/heights.md.
constexpr std::array kRows = std::to_array<Row>({
    {T::Generic, R::Other, {6, 12}},       {T::Residential, R::Other, {9, 15}},
    {T::House, R::Other, {6, 10}},         {T::Apartments, R::Other, {12, 21}},
    {T::Commercial, R::Other, {6, 15}},    {T::Retail, R::Other, {4, 8}},
    {T::Office, R::Other, {12, 30}},       {T::Industrial, R::Other, {6, 10}},
    {T::Warehouse, R::Other, {6, 10}},     {T::Religious, R::Other, {12, 20}},
    {T::Civic, R::Other, {8, 15}},         {T::School, R::Other, {9, 15}},
    {T::Hospital, R::Other, {12, 25}},     {T::Hotel, R::Other, {12, 30}},
    {T::Garage, R::Other, {2.7f, 3.3f}},   {T::Shed, R::Other, {2.2f, 2.8f}},
    {T::Roof, R::Other, {3, 5}},
    // European towns: blocks of 4-6 storeys around courtyards, shops in their ground floors;
    // "yes" covers those blocks and village houses alike.
    {T::Generic, R::Europe, {8, 15}},      {T::Residential, R::Europe, {13, 19}},
    {T::Apartments, R::Europe, {14, 21}},  {T::Commercial, R::Europe, {10, 18}},
    {T::Retail, R::Europe, {6, 12}},       {T::Office, R::Europe, {12, 21}},
    {T::Hotel, R::Europe, {15, 22}},
    // North America: residential means houses; downtown towers carry tags.
    {T::Generic, R::NorthAmerica, {5, 11}}, {T::Residential, R::NorthAmerica, {6, 12}},
    {T::Apartments, R::NorthAmerica, {9, 15}}, {T::Office, R::NorthAmerica, {15, 40}},
    // East Asian cities: slabs of flats.
    {T::Generic, R::EastAsia, {9, 18}},    {T::Residential, R::EastAsia, {15, 36}},
    {T::Apartments, R::EastAsia, {30, 60}},
});

struct Box {
    Region region;
    double minLat, maxLat, minLon, maxLon;
};

constexpr std::array kRegions = std::to_array<Box>({
    {R::Europe, 34, 72, -25, 60},
    {R::NorthAmerica, 15, 72, -170, -50},
    {R::EastAsia, 0, 55, 95, 150},
});

} // namespace

Region regionOf(double lat, double lon) {
    for (const Box& b : kRegions)
        if (lat >= b.minLat && lat <= b.maxLat && lon >= b.minLon && lon <= b.maxLon) return b.region;
    return R::Other;
}

HeightSpan typicalHeight(BuildingType type, Region region) {
    HeightSpan span;
    for (const Row& row : kRows)
        if (row.type == type && (row.region == region || row.region == R::Other)) span = row.span;
    return span;
}

} // namespace urbis
