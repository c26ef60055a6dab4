#include "streets/water_depth.h"

#include "streets/street_levels.h"

#include <algorithm>
#include <cstdint>
#include <map>
#include <utility>

namespace urbis {

namespace {

/// The bed's cells near the shore are half the shelf across (1 m at least): the depth is linear
/// within a triangle, and two steps draw the bank's curve well enough under water (a quarter made San
/// Francisco's bay 82,000 triangles and its meshing seconds longer).
constexpr double kCellsPerShelf = 2.0;

} // namespace

float waterSurfaceLevel() { return kWaterLevel; }

float waterBedDepth(double distance, const WaterOptions& options) {
    const double t = options.shelfWidth > 0 ? std::clamp(distance / options.shelfWidth, 0.0, 1.0) : 1.0;
    return std::max(kMinBedDepth, float(options.maxDepth * (1.0 - (1.0 - t) * (1.0 - t))));
}

size_t meshWaterBed(const CoverShapes& shapes, size_t shape, const WaterOptions& options, TriangleInfo info,
                    TriangleMesh& mesh) {
    const double cell = std::max(1.0, options.shelfWidth / kCellsPerShelf);
    const std::vector<PlaneTriangle> triangles = shapes.trianglesNearBoundary(shape, cell, options.shelfWidth);
    // Each vertex is shared by about six triangles: its distance to the shore is asked once.
    std::map<std::pair<double, double>, uint32_t> index;
    std::vector<Vec2d> points;
    std::vector<uint32_t> corners;
    corners.reserve(triangles.size() * 3);
    for (const PlaneTriangle& t : triangles)
        for (const Vec2d p : t) {
            const auto [it, added] = index.try_emplace({p.x, p.y}, uint32_t(points.size()));
            if (added) points.push_back(p);
            corners.push_back(it->second);
        }
    const std::vector<double> distance = shapes.distancesToBoundary(shape, points);
    auto world = [&](size_t corner) {
        const uint32_t i = corners[corner];
        return Vec3f{float(points[i].x), -waterBedDepth(distance[i], options), float(-points[i].y)};
    };
    for (size_t i = 0; i < triangles.size(); ++i) mesh.add({world(3 * i), world(3 * i + 1), world(3 * i + 2)}, info);
    return triangles.size();
}

} // namespace urbis
