// CityModel -> stored triangles: every building's walls and roof, and a ground plane.
#pragma once

#include "citygen/triangle_mesh.h"
#include "math/bounds.h"
#include "model/city_model.h"
#include "scene/material.h"

#include <map>
#include <string>

namespace urbis {

/// Object ids: 0 is the ground, building i of the CityModel is i + 1.
constexpr uint32_t kGroundObject = 0;

struct CityMesh {
    TriangleMesh mesh;
    std::vector<Material> materials;
    Bounds3f cityBounds;                       ///< world bounds of the buildings (ground excluded)
    std::map<std::string, size_t> trianglesByKind;
    std::map<std::string, uint64_t> dropped;   ///< buildings that could not be meshed, by reason
};

/// Meshes the whole city in parallel; the result does not depend on the thread count.
CityMesh meshCity(const CityModel& city);

} // namespace urbis
