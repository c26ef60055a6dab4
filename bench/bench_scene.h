// The triangles every accel benchmark traces: one function, so the scene source can change.
#pragma once

#include "scene/triangle.h"

#include <vector>

namespace urbis::bench {

/// The benchmark scene in world space (metres, y up). For now a generated city of about a
/// million triangles: closed boxes of varied heights on a grid of lots, some with a
/// set-back upper part, on a ground plane. To be replaced by an imported city extract.
std::vector<Triangle> benchTriangles();

} // namespace urbis::bench
