// Shared by the road network's tests: hand-made cities, the network meshed on the ground, vertical
// rays through it, and how much of a plan polygon a triangle covers.
#pragma once

#include "geometry/scene_intersect.h"
#include "model/cell_grid.h"
#include "scene/scene.h"
#include "streets/junction_shapes.h"
#include "streets/road_fitting.h"
#include "streets/street_materials.h"
#include "streets/street_network.h"
#include "streets/street_network_plane.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace urbis::test {

/// A residential two-lane road along `line`, sidewalks both sides.
inline Road street(std::vector<Vec2d> line, float width = 6.0f, Sidewalk sidewalk = Sidewalk::Both) {
    Road r;
    r.centerline = std::move(line);
    r.width = width;
    r.sidewalk = sidewalk;
    return r;
}

/// Roads from (0, 0) out `length` m at each angle (degrees), with their widths.
inline CityModel star(const std::vector<double>& degrees, const std::vector<float>& widths, double length = 40.0) {
    CityModel city;
    for (size_t i = 0; i < degrees.size(); ++i) {
        const double a = degrees[i] * std::numbers::pi / 180.0;
        city.roads.push_back(street({{0, 0}, {length * std::cos(a), length * std::sin(a)}}, widths[i]));
    }
    return city;
}

/// A rectangular footprint [x0, x1] x [y0, y1], counter-clockwise.
inline Building box(double x0, double y0, double x1, double y1) {
    Building b;
    b.footprint.outer = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
    return b;
}

/// The network of a city, fitted, on flat ground, and the scene of it with the ground at 0.
struct Network {
    std::vector<Road> fitted;
    std::vector<std::vector<float>> elevations;
    StreetMesh mesh;
    StreetJunctions shapes;
    Scene scene;

    explicit Network(const CityModel& city) {
        fitted = fitRoads(city, mesh.dropped);
        for (const Road& r : fitted) elevations.emplace_back(r.centerline.size(), 0.0f);
        meshStreetNetwork(city, fitted, elevations, StreetOptions{}, mesh);
        shapes = shapeJunctions(fitted, elevations);
        scene = Scene::build({.mesh = mesh.mesh, .materials = streetMaterials(),
                              .grounds = {GroundRecord::around(0, 0, 0, 0)}});
    }

    /// What a vertical ray down through plan point p meets first.
    SurfaceHit down(Vec2d p) const {
        return intersectScene(scene.view(), Ray{{float(p.x), 50.0f, float(-p.y)}, {0, -1, 0}});
    }
};

inline bool isGround(const SurfaceHit& h) { return !h.valid() || h.kind == kPrimKindOf<GroundRecord>; }

/// Whether p lies inside the polygon (even-odd).
inline bool inside(const std::vector<Vec2d>& ring, Vec2d p) {
    bool in = false;
    for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++)
        if ((ring[i].y > p.y) != (ring[j].y > p.y) &&
            p.x < ring[j].x + (ring[i].x - ring[j].x) * (p.y - ring[j].y) / (ring[i].y - ring[j].y))
            in = !in;
    return in;
}

inline double distanceToRing(const std::vector<Vec2d>& ring, Vec2d p) {
    double best = 1e30;
    for (size_t i = 0; i < ring.size(); ++i) {
        const Vec2d a = ring[i], b = ring[(i + 1) % ring.size()];
        const double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
        const double t = l2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / l2, 0.0, 1.0) : 0.0;
        best = std::min(best, std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy));
    }
    return best;
}

/// Plan area of `polygon` inside the triangle a b c (Sutherland-Hodgman against its three sides).
inline double areaInTriangle(std::vector<Vec2d> polygon, Vec2d a, Vec2d b, Vec2d c) {
    const double orient = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    if (orient < 0) std::swap(b, c);
    const Vec2d tri[3] = {a, b, c};
    for (int e = 0; e < 3 && !polygon.empty(); ++e) {
        const Vec2d p = tri[e], q = tri[(e + 1) % 3];
        const auto side = [&](Vec2d v) { return (q.x - p.x) * (v.y - p.y) - (q.y - p.y) * (v.x - p.x); };
        std::vector<Vec2d> clipped;
        for (size_t i = 0; i < polygon.size(); ++i) {
            const Vec2d u = polygon[i], v = polygon[(i + 1) % polygon.size()];
            const double su = side(u), sv = side(v);
            if (su >= 0) clipped.push_back(u);
            if ((su >= 0) != (sv >= 0)) {
                const double t = su / (su - sv);
                clipped.push_back({u.x + (v.x - u.x) * t, u.y + (v.y - u.y) * t});
            }
        }
        polygon = std::move(clipped);
    }
    double area = 0;
    for (size_t i = 0; i < polygon.size(); ++i) {
        const Vec2d u = polygon[i], v = polygon[(i + 1) % polygon.size()];
        area += u.x * v.y - v.x * u.y;
    }
    return std::fabs(area) * 0.5;
}

/// Flat street triangles (tops of carriageways, junctions, sidewalks, paths) filed by their plan boxes.
struct FlatTriangles {
    std::vector<uint32_t> index;
    CellGrid grid{10.0};
    const TriangleMesh& mesh;

    explicit FlatTriangles(const TriangleMesh& m) : mesh(m) {
        for (uint32_t i = 0; i < m.size(); ++i) {
            const Triangle& t = m.triangles[i];
            if (t.p0.y != t.p1.y || t.p0.y != t.p2.y) continue;
            grid.insert(i, {Vec2d{std::min({t.p0.x, t.p1.x, t.p2.x}), std::min({-t.p0.z, -t.p1.z, -t.p2.z})},
                            Vec2d{std::max({t.p0.x, t.p1.x, t.p2.x}), std::max({-t.p0.z, -t.p1.z, -t.p2.z})}});
        }
    }

    /// How many flat triangles at height y hold plan point p strictly inside (by `margin` m).
    int covering(Vec2d p, float y, double margin = 1e-4) const {
        std::vector<uint32_t> found;
        grid.query({p, p}, [&](uint32_t i) { found.push_back(i); });
        std::sort(found.begin(), found.end());
        found.erase(std::unique(found.begin(), found.end()), found.end());
        int count = 0;
        for (uint32_t i : found) {
            const Triangle& t = mesh.triangles[i];
            if (std::fabs(t.p0.y - y) > 1e-4f) continue;
            const Vec2d v[3] = {{t.p0.x, -t.p0.z}, {t.p1.x, -t.p1.z}, {t.p2.x, -t.p2.z}};
            bool in = true;
            double sign = 0;
            for (int e = 0; e < 3 && in; ++e) {
                const Vec2d a = v[e], b = v[(e + 1) % 3];
                const double l = std::hypot(b.x - a.x, b.y - a.y);
                const double s = ((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x)) / l;
                if (sign == 0) sign = s > 0 ? 1 : -1;
                in = s * sign > margin;
            }
            count += in ? 1 : 0;
        }
        return count;
    }
};

} // namespace urbis::test
