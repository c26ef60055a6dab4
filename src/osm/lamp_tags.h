// Street-lamp attributes from OSM tags.
#pragma once

#include "model/city_model.h"
#include "osm/tag_lookup.h"

#include <cstdint>

namespace urbis {

/// Lamp attributes (all but position) of a `highway=street_lamp` node:
///  - mount: `lamp_mount` (straight_mast, cast_steel -> Pole; bent_mast; wall, wall_mounted;
///    suspended, wire; ground), else `support` (pole, wall_mounted, suspended, ground), else Pole;
///  - head: `lamp_type`, else `light:shape` when they name a shape (lantern, globe, cone, flat,
///    cobra...); else by mount and method (cast_steel and gas: lantern; suspended: cone;
///    ground: flat; else cobra);
///  - height: `height`, else by mount (wall 4.5 m, suspended 7 m, ground 1 m, else 6 m);
///  - colour temperature: `light:colour`, else by `light:method` or `lamp_type` (sodium
///    2000 K, low-pressure sodium 1800 K, mercury 4000 K, metal halide 3200 K, LED and
///    fluorescent 4000 K, gas and incandescent 2700 K), else 0;
///  - `light:count`, `light:direction` (degrees or compass points), `lampType` as tagged.
Lamp lampFromTags(const TagLookup& tag, int64_t osmId);

} // namespace urbis
