#include "layout/lots.h"

#include "math/hash.h"

#include <algorithm>

namespace urbis {

namespace {

// Lot widths along the frontage in metres, per district (Centre, Middle, Outskirts).
constexpr float kLotWidth[3][2] = {{16.0f, 32.0f}, {12.0f, 22.0f}, {10.0f, 16.0f}};
// Probability that a block in the centre is one lot (a perimeter block or a tower).
constexpr float kWholeBlockChance = 0.2f;
// A block shallower than this (metres) gets one row of lots instead of two back to back.
constexpr double kMinTwoRowDepth = 28.0;

} // namespace

Rect2d Lot::bounds() const {
    Vec2d a = at(0, 0), b = at(width, depth);
    return {std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y)};
}

void subdivideBlock(const Rect2d& block, District district, uint32_t key, std::vector<Lot>& out) {
    if (block.width() <= 0 || block.height() <= 0) return;
    HashStream rng{key};
    if (district == District::Centre && rng.uniform() < kWholeBlockChance) {
        out.push_back({{block.x0, block.y0}, {0, 1}, block.width(), block.height(), district, true});
        return;
    }
    const int rows = block.height() >= kMinTwoRowDepth ? 2 : 1;
    const double depth = block.height() / rows;
    const float* range = kLotWidth[static_cast<int>(district)];
    double x = block.x0;
    while (x < block.x1) {
        double w = rng.uniform(range[0], range[1]);
        if (block.x1 - x - w < range[0]) w = block.x1 - x;  // the last lot takes the rest
        // The south row faces the southern street; the north row, mirrored, the northern one.
        out.push_back({{x, block.y0}, {0, 1}, w, depth, district, false});
        if (rows == 2) out.push_back({{x + w, block.y1}, {0, -1}, w, depth, district, false});
        x += w;
    }
}

} // namespace urbis
