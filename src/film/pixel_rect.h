// A rectangle of a film's pixels: the unit a tile renderer works on and a tile message carries.
#pragma once

#include <cstddef>
#include <cstdint>

namespace urbis {

/// Pixels x0 <= x < x1, y0 <= y < y1 of a film, rows from the top.
struct PixelRect {
    uint32_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;

    uint32_t width() const { return x1 - x0; }
    uint32_t height() const { return y1 - y0; }
    size_t pixels() const { return size_t(width()) * height(); }
    bool operator==(const PixelRect&) const = default;
};

} // namespace urbis
