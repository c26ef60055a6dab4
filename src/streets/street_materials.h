// The streets' materials, one fixed list (a scene description may change them later): surfaces by
// `surface=*`, paint, ground cover, water, bridges, railways and lamps.
#pragma once

#include "model/city_model.h"
#include "scene/material.h"

#include <cstdint>
#include <vector>

namespace urbis {

enum class StreetMaterial : uint32_t {
    Asphalt, Concrete, PavingStones, Sett, Cobblestone, Gravel, Dirt, Grass, Wood, Metal,  // RoadSurface order
    PaintWhite, PaintYellow,      // PaintYellow must follow PaintWhite (RoadSegment::paint + 1)
    Sidewalk, Curb,
    Park, Lawn, ForestFloor, ResidentialGround, CommercialGround, IndustrialGround, Pitch, Playground,
    Sand, Scrub, Parking, Cemetery, Farmland,
    Water,
    BridgeConcrete, Parapet,
    Ballast, RailSteel,
    LampMetal, LampHousing, LampGlass,
    WaterBed,                     // the dark bottom under a water surface
    Count
};

/// The materials of StreetMaterial, in its order.
std::vector<Material> streetMaterials();

/// The StreetMaterial of a road surface (Unknown: asphalt).
StreetMaterial materialOf(RoadSurface surface);

} // namespace urbis
