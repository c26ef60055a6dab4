// Footprints and one-building meshing shared by the roof tests.
#pragma once

#include "citygen/city_mesher.h"

#include <cmath>
#include <numbers>

namespace urbis::test {

/// Every RoofShape, Unknown included.
inline constexpr RoofShape kAllShapes[] = {RoofShape::Flat,      RoofShape::Skillion, RoofShape::Gabled,  RoofShape::Hipped,
                                           RoofShape::Pyramidal, RoofShape::Dome,     RoofShape::Onion,   RoofShape::Gambrel,
                                           RoofShape::Mansard,   RoofShape::Round,    RoofShape::Unknown};

inline Polygon rectangle(double w, double d) { return {{{0, 0}, {w, 0}, {w, d}, {0, d}}, {}}; }

inline Polygon lShape() { return {{{0, 0}, {20, 0}, {20, 8}, {8, 8}, {8, 20}, {0, 20}}, {}}; }

inline Polygon courtyard() { return {{{0, 0}, {30, 0}, {30, 20}, {0, 20}}, {{{10, 5}, {10, 15}, {20, 15}, {20, 5}}}}; }

/// A regular n-gon of circumradius r about (x, y), counter-clockwise.
inline Polygon regularPolygon(int n, double r, double x = 0, double y = 0) {
    Polygon p;
    for (int i = 0; i < n; ++i) {
        const double a = 2 * std::numbers::pi * i / n;
        p.outer.push_back({x + r * std::cos(a), y + r * std::sin(a)});
    }
    return p;
}

inline double ringArea(const Ring& ring) {
    double a = 0;
    for (size_t i = 0; i < ring.size(); ++i) {
        const Vec2d p = ring[i], q = ring[(i + 1) % ring.size()];
        a += p.x * q.y - q.x * p.y;
    }
    return 0.5 * a;
}

inline Building roofed(Polygon footprint, RoofShape shape, float minHeight, float height, float roofHeight) {
    Building b;
    b.footprint = std::move(footprint);
    b.roofShape = shape;
    b.minHeight = minHeight;
    b.height = height;
    b.roofHeight = roofHeight;
    return b;
}

/// Mesher options for closed mass models: plain walls instead of facades, and no streets.
inline CityMeshOptions massModel() {
    CityMeshOptions options;
    options.geometry.walls = Representation::Plain;
    options.streets = false;
    return options;
}

/// The city mesh of one building, as a closed mass model.
inline CityMesh meshOne(const Building& b) {
    CityModel city;
    city.buildings = {b};
    return meshCity(city, massModel());
}

} // namespace urbis::test
