#include "cluster/film_tiles.h"

#include <cstring>
#include <stdexcept>
#include <type_traits>

namespace urbis {

namespace {

/// Calls `copy(firstPixelOfRow, rowBytes)` for each row of `rect` in each array the film keeps.
template <class FilmT, class Copy>
void forEachRectRow(FilmT& film, const PixelRect& rect, Copy&& copy) {
    forEachFilmArray(
        [&](auto, bool, auto& array) {
            if (array.empty()) return;
            using T = std::remove_cvref_t<decltype(array[0])>;
            for (uint32_t y = rect.y0; y < rect.y1; ++y)
                copy(array.data() + (size_t(y) * film.width + rect.x0), rect.width() * sizeof(T));
        },
        film.arrays);
}

} // namespace

std::vector<uint8_t> packFilmRect(const Film& film, const PixelRect& rect) {
    std::vector<uint8_t> bytes;
    forEachRectRow(film, rect, [&](const auto* row, size_t n) {
        const auto* first = reinterpret_cast<const uint8_t*>(row);
        bytes.insert(bytes.end(), first, first + n);
    });
    return bytes;
}

void unpackFilmRect(const std::vector<uint8_t>& bytes, const PixelRect& rect, Film& film) {
    size_t expected = 0;
    forEachRectRow(film, rect, [&](auto*, size_t n) { expected += n; });
    if (bytes.size() != expected) throw std::invalid_argument("unpackFilmRect: the bytes are not the rectangle's");
    size_t at = 0;
    forEachRectRow(film, rect, [&](auto* row, size_t n) {
        std::memcpy(row, bytes.data() + at, n);
        at += n;
    });
}

} // namespace urbis
