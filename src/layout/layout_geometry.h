// Small 2D helpers shared by the layout files: axis-aligned rectangles in local metres.
#pragma once

#include "model/city_model.h"

namespace urbis {

/// An axis-aligned rectangle in local metres (x east, y north).
struct Rect2d {
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    double width() const { return x1 - x0; }
    double height() const { return y1 - y0; }
    Vec2d centre() const { return {0.5 * (x0 + x1), 0.5 * (y0 + y1)}; }
};

/// The rectangle as a counter-clockwise ring, in metres.
inline Ring ringOf(const Rect2d& r) { return {{r.x0, r.y0}, {r.x1, r.y0}, {r.x1, r.y1}, {r.x0, r.y1}}; }

} // namespace urbis
