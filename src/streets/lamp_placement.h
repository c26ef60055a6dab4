// Where street lamps stand (host): every mapped lamp, and along the roads that have none mapped,
// lamps at a spacing by class, on the sidewalk, clear of buildings, carriageways and junctions.
#pragma once

#include "model/city_model.h"

#include <vector>

namespace urbis {

/// How a class of road is lit: lamps `spacing` metres apart (0: none), of this mount, head and height.
struct LampStyle {
    double spacing = 0;
    LampMount mount = LampMount::Pole;
    LampHead head = LampHead::Cobra;
    float height = 6.0f;
    float colourTemperature = 4000.0f;
};

/// The lamps of a class: motorways and trunk roads 40 m, primary and secondary 30 m (bent masts with
/// cobra heads, 8-10 m), tertiary 35 m (flat LED heads on bent masts, 7 m), residential and
/// unclassified 38 m (cones on 5.5 m posts), living streets, pedestrian streets and service roads
/// 25 m (lanterns and globes, 4-4.5 m); none on footways, cycleways, paths, steps and tracks
/// (unlit, or lit by the road beside them).
LampStyle lampStyle(HighwayClass highway);

/// Every lamp of `city.lamps` (a head leaning nowhere, direction -1, turned to the nearest road),
/// then lamps placed along `roads` (the fitted roads: width and sidewalk widths as given, 0 = no
/// sidewalk that side) where no mapped lamp stands within half a spacing: one row on the side with a
/// sidewalk (or the right; a blocked station tries the other side) below 10 m of carriageway, two
/// staggered rows from 10 m, one row on the
/// centre line of a two-way road wider than 20 m (a dual carriageway drawn as one way), each 0.5 m
/// from the curb onto the sidewalk, or 0.5 m beyond the edge where there is none. A position is left
/// out within 0.5 m of a building footprint, on any carriageway (within its half width + 0.2 m of a
/// centerline), near a junction (within max(8 m, half its widest road + 4 m) of a node where three
/// or more road edges meet) or within 0.4 spacings of a lamp already placed. Heads lean towards the
/// road. Deterministic: roads in order, fixed queries.
std::vector<Lamp> streetLamps(const CityModel& city, const std::vector<Road>& roads);

/// Whether a road carries lamps along it at all: a lit class on the surface (no tunnel, underground,
/// covered or area way, at least two points).
bool litRoad(const Road& road);

} // namespace urbis
