#include "osm/building_use.h"

#include "osm/tag_parsing.h"

#include <array>
#include <string_view>

namespace urbis {

namespace {

/// A use tag and the type it implies; a null value matches any value but "no".
struct UseRow {
    const char* key;
    const char* value;
    BuildingType type;
};

using T = BuildingType;
constexpr std::array<UseRow, 26> kUses = {{
    {"amenity", "place_of_worship", T::Religious}, {"historic", "church", T::Religious},
    {"tower:type", "bell_tower", T::Religious},
    {"amenity", "school", T::School}, {"amenity", "kindergarten", T::School},
    {"amenity", "college", T::School}, {"amenity", "university", T::School},
    {"amenity", "hospital", T::Hospital}, {"amenity", "clinic", T::Hospital},
    {"tourism", "hotel", T::Hotel}, {"tourism", "hostel", T::Hotel}, {"tourism", "guest_house", T::Hotel},
    {"amenity", "townhall", T::Civic}, {"amenity", "fire_station", T::Civic}, {"amenity", "police", T::Civic},
    {"amenity", "library", T::Civic}, {"amenity", "courthouse", T::Civic},
    {"amenity", "community_centre", T::Civic}, {"amenity", "theatre", T::Civic},
    {"railway", "station", T::Civic}, {"public_transport", "station", T::Civic},
    {"office", nullptr, T::Office}, {"shop", nullptr, T::Retail}, {"amenity", "parking", T::Garage},
    {"man_made", "works", T::Industrial}, {"industrial", nullptr, T::Industrial},
}};

bool matches(const UseRow& row, const TagLookup& tag) {
    const char* value = tag(row.key);
    if (!value) return false;
    const std::string_view v = trim(value);
    return row.value ? v == row.value : v != "no";
}

} // namespace

BuildingType buildingTypeFromTags(const TagLookup& tag) {
    const char* building = tag("building");
    if (!building) building = tag("building:part");
    const BuildingType named = building ? parseBuildingType(building) : T::Generic;
    if (named != T::Generic) return named;
    for (const UseRow& row : kUses)
        if (matches(row, tag)) return row.type;
    return T::Generic;
}

} // namespace urbis
