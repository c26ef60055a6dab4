#include "prepare/camera_checks.h"

#include "model/polygon_ops.h"

#include <cmath>
#include <cstdio>

namespace urbis {

namespace {

/// The building whose volume holds world point `p`, or nullptr.
const Building* buildingAt(const CityModel& city, Vec3f p) {
    const Vec2d local{p.x, -p.z};  // world z points south, local y north
    for (const Building& b : city.buildings) {
        if (p.y < b.minHeight || p.y > b.height) continue;
        const std::array<Vec2d, 2> box = bounds(b.footprint.outer);
        if (local.x < box[0].x || local.x > box[1].x || local.y < box[0].y || local.y > box[1].y) continue;
        if (contains(b.footprint, local)) return &b;
    }
    return nullptr;
}

std::string format(const char* pattern, double a, double b = 0, double c = 0) {
    char line[200];
    std::snprintf(line, sizeof line, pattern, a, b, c);
    return line;
}

} // namespace

std::vector<std::string> cameraProblems(const Camera& camera, const CityModel& city, const Bounds3f& cityBounds) {
    std::vector<std::string> problems;
    const Vec3f p = camera.position;
    if (const Building* b = buildingAt(city, p)) {
        std::string id = b->osmId > 0 ? " (way " + std::to_string(b->osmId) + ")"
                         : b->osmId < 0 ? " (relation " + std::to_string(-b->osmId) + ")" : "";
        problems.push_back(format("the camera (%.1f, %.1f, %.1f) is inside a building", p.x, p.y, p.z) + id);
    }
    if (p.y < 0.0f) problems.push_back(format("the camera is %.1f m under the ground", -p.y));
    if (!cityBounds.empty()) {
        const Vec3f c = cityBounds.centre(), e = cityBounds.extent();
        const double distance = std::hypot(double(p.x - c.x), double(p.z - c.z));
        const double diagonal = std::hypot(double(e.x), double(e.z));
        if (distance > diagonal + kFarCameraMargin)
            problems.push_back(format("the camera is %.0f m from the city's centre, farther than its extent (%.0f m) "
                                      "+ %.0f m",
                                      distance, diagonal, kFarCameraMargin));
    }
    return problems;
}

} // namespace urbis
