// The streets' materials, one fixed list (a scene description may change them later): surfaces by
// `surface=*`, paint, ground cover, water, bridges, railways and lamps.
#pragma once

#include "model/city_model.h"
#include "scene/material.h"
#include "streets/water_options.h"

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
    WaterBed,                     // the bed under a water surface, darkened by the water's depth
    Count
};

/// The materials of StreetMaterial, in its order; the water's and its bed's from `water`.
std::vector<Material> streetMaterials(const WaterOptions& water = {});

/// The material of a water surface: a dielectric interface of water's index (1.33) with the
/// absorption and the wind of `water`. Its refracted rays pass the layer down to the ground's plane
/// (skipBelow = waterSurfaceLevel's height above it) to find the bed below.
Material waterMaterial(const WaterOptions& water);

/// The StreetMaterial of a road surface (Unknown: asphalt).
StreetMaterial materialOf(RoadSurface surface);

} // namespace urbis
