#include "streets/water_depth.h"

#include "streets/street_levels.h"

#include <algorithm>

namespace urbis {

namespace {

/// The bed's cells near the shore are a quarter of the shelf across (1 m at least): the depth is
/// linear within a triangle, so four steps draw the bank's curve.
constexpr double kCellsPerShelf = 4.0;

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
    std::vector<Vec2d> points;
    points.reserve(triangles.size() * 3);
    for (const PlaneTriangle& t : triangles) points.insert(points.end(), t.begin(), t.end());
    const std::vector<double> distance = shapes.distancesToBoundary(shape, points);
    auto world = [&](size_t i) { return Vec3f{float(points[i].x), -waterBedDepth(distance[i], options), float(-points[i].y)}; };
    for (size_t i = 0; i < triangles.size(); ++i) mesh.add({world(3 * i), world(3 * i + 1), world(3 * i + 2)}, info);
    return triangles.size();
}

} // namespace urbis
