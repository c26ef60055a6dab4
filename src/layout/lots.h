// Blocks to lots: a block is split into one or two rows of lots along its street frontages.
#pragma once

#include "layout/district.h"
#include "layout/layout_geometry.h"

#include <cstdint>
#include <vector>

namespace urbis {

/// A rectangular lot facing a street. Local coordinates: s along the frontage in
/// direction frontage() (the inward direction turned clockwise), t inward from the street;
/// the lot covers s in [0, width], t in [0, depth]. The map is a rotation, so a ring that
/// is counter-clockwise in (s, t) stays counter-clockwise in (x, y).
struct Lot {
    Vec2d front;                  ///< m, the corner where s = 0, t = 0
    Vec2d inward;                 ///< unit and axis-aligned: from the street into the block
    double width = 0, depth = 0;  ///< m
    District district = District::Outskirts;
    bool wholeBlock = false;      ///< the lot is a whole block, bordered by streets on all sides

    Vec2d frontage() const { return {inward.y, -inward.x}; }
    /// The point in metres at lot coordinates (s, t) in metres.
    Vec2d at(double s, double t) const {
        Vec2d u = frontage();
        return {front.x + s * u.x + t * inward.x, front.y + s * u.y + t * inward.y};
    }
    /// The lot as an axis-aligned rectangle in metres.
    Rect2d bounds() const;
};

/// Appends the lots of one block (its buildable rectangle in metres) to `out`; `key` seeds
/// the lot widths, which depend on the district.
void subdivideBlock(const Rect2d& block, District district, uint32_t key, std::vector<Lot>& out);

} // namespace urbis
