// A building's broad type from its tags: the `building` value, or for a bare `building=yes`
// what the object is used for. A pure, table-driven step (tests/osm_building_use_test.cpp).
#pragma once

#include "model/city_model.h"
#include "osm/tag_lookup.h"

namespace urbis {

/// The type of a building or building:part: parseBuildingType of `building` (else of
/// `building:part`); where that says nothing (yes, unlisted or missing), the first use tag
/// that names one: `amenity=place_of_worship`, `historic=church`, `tower:type=bell_tower` ->
/// Religious; `amenity=school|kindergarten|college|university` -> School;
/// `amenity=hospital|clinic` -> Hospital; `tourism=hotel|hostel|guest_house` -> Hotel;
/// `amenity=townhall|fire_station|police|library|courthouse|community_centre|theatre` and
/// `railway|public_transport=station` -> Civic; `office=*` -> Office; `shop=*` -> Retail;
/// `amenity=parking` -> Garage; `man_made=works`, `industrial=*` -> Industrial. So a church
/// or its tower mapped as `building=yes` on the place of worship styles as a church.
BuildingType buildingTypeFromTags(const TagLookup& tag);

} // namespace urbis
