// Whether a building or building:part lies entirely below ground, from its tags: a pure,
// table-driven step, tested apart from geometry (tests/osm_underground_test.cpp).
#pragma once

#include "osm/tag_lookup.h"

namespace urbis {

/// True when the tags say the whole object is below ground, so that it must not stand as a
/// block on the surface (a metro station hall, an underground car park, a basement shop):
///  - `location=underground` (also in a list: `underground;indoor`), unless the list also
///    names an above-ground place (`surface`, `overground`, `roof`, ...);
///  - `tunnel=*` other than `no`, `building_passage` (a passage through a standing
///    building) and `avalanche_protector` (a gallery on the surface);
///  - `level` or `building:level` whose every value lies below 0 ("-1",
///    "-2;-1", "-1--3", "-0.9"); "-1;0;1" spans the ground floor and is kept;
///  - `max_level` / `building:max_level` below 0 (the top storey is underground);
///  - `building:levels=0` with `building:levels:underground` >= 1;
///  - `building=underground` (or `building:part=underground`);
///  - `parking=underground` on a car park (`amenity=parking`, or a building value that
///    names none other than one: yes, parking, garage, garages).
/// An explicit `location=surface` / `overground` / `roof` keeps the object whatever else it
/// says. `layer<0` alone is no evidence: the wiki (Key:layer) defines layer only as the
/// vertical order of features that cross, and mappers put layer=-1 on buildings below a
/// podium, bridge or roof that stand at street level (London's Lambert Jones Mews under the
/// Barbican, San Francisco's 30 m Salesforce Transit Center). Positive or negative
/// `min_level` / `building:min_level` alone says where a part starts (a bridge between
/// buildings at min_level=3, a station whose lowest floor is -2 under a tall hall): kept.
bool isUnderground(const TagLookup& tag);

} // namespace urbis
