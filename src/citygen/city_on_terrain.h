// The city stood on the terrain, at build time on the host, so that the per-ray code of walls,
// roofs, roads and lamps stays as it is: every building is raised to the highest ground under its
// footprint (its entrance level, where its floors start) and its walls continued down to the lowest
// (no gap on a slope); the streets' surfaces are cut where the ground bends under them, into pieces
// down to two sample spacings, and each vertex raised by the ground under it; lamps and trees stand on the ground;
// water lies flat at its body's level (citygen/water_on_terrain.h) over the terrain, its bed.
#pragma once

#include "citygen/city_mesher.h"
#include "citygen/water_on_terrain.h"
#include "scene/terrain_field.h"

namespace urbis {

/// The shortest edge (metres) a street triangle is split to on bending ground: twice its sample spacing.
float streetEdgeOnTerrain(const TerrainField& terrain);

/// Places `mesh` (built on the flat ground y = 0) on `terrain` as the file's comment says, and moves
/// its cityBounds and framingPieces with it. The surface of each water body in `water` lies at its level
/// and its bed's triangles go (the terrain, carved by carveWaterBeds, is the bed).
void placeCityOnTerrain(CityMesh& mesh, const TerrainField& terrain, const WaterLevels& water = {});

} // namespace urbis
