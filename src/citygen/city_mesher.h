// CityModel -> stored triangles: every building's walls and roof, and the ground's material.
#pragma once

#include "citygen/triangle_mesh.h"
#include "math/bounds.h"
#include "model/city_model.h"
#include "scene/material.h"

#include <map>
#include <string>

namespace urbis {

struct CityMesh {
    TriangleMesh mesh;
    std::vector<Material> materials;
    uint32_t groundMaterial = 0;               ///< the ground plane's entry in materials
    Bounds3f cityBounds;                       ///< world bounds of the buildings (ground excluded)
    std::map<std::string, size_t> trianglesByKind;
    std::map<std::string, uint64_t> dropped;   ///< buildings that could not be meshed, by reason
    std::map<std::string, uint64_t> roofFallbacks;  ///< roofs meshed as a simpler shape (unknown shape -> flat, ...), by reason
};

/// Meshes the whole city (object id of building i is i + 1; 0 is the ground) in parallel; the result does not depend on the thread count.
CityMesh meshCity(const CityModel& city);

} // namespace urbis
