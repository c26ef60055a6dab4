// A meshed city as an ExportScene: the twin's triangles grouped into a node per building and a node
// per street kind, the flat ground or the terrain as a mesh, materials in PBR terms.
#pragma once

#include "citygen/city_mesher.h"
#include "export/export_scene.h"
#include "model/city_model.h"
#include "scene/camera.h"
#include "scene/sun.h"
#include "scene/terrain_field.h"

namespace urbis {

/// The export of `mesh`, meshed from `city` (object i + 1 of a building part is building i; the streets' parts are grouped by
/// their SurfacePart into "roads", "junctions", "sidewalks", "ground_cover", "water", "bridges",
/// "railways", "lamps", "trees"), standing on `terrain` (meshed cell by cell, each triangle with the
/// terrain's material at its centre) or, where empty, on a flat "ground" square reaching 100 m past
/// everything else. Building nodes carry the OSM id and tags; the asset's extras the origin's
/// lon/lat. Only the materials some triangle uses are kept.
ExportScene exportSceneOf(const CityModel& city, const CityMesh& mesh, const TerrainField& terrain,
                          const Camera& camera, const Sun& sun);

} // namespace urbis
