// Triangles as an indexed mesh: vertices that are equal bit for bit become one, as file formats want.
#pragma once

#include "math/vec.h"
#include "scene/triangle.h"

#include <cstdint>
#include <vector>

namespace urbis {

struct WeldedMesh {
    std::vector<Vec3f> positions;
    std::vector<uint32_t> indices;   ///< three per triangle, in the triangles' order and winding
    Vec3f lo{0, 0, 0}, hi{0, 0, 0};  ///< of the positions (glTF's accessor min and max)
};

/// The indexed mesh of `triangles`, positions in first-use order.
WeldedMesh weldTriangles(const std::vector<Triangle>& triangles);

} // namespace urbis
