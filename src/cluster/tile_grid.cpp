#include "cluster/tile_grid.h"

#include <algorithm>
#include <stdexcept>

namespace urbis {

std::vector<PixelRect> tilesOf(uint32_t width, uint32_t height, uint32_t tileSize) {
    if (tileSize == 0) throw std::invalid_argument("tilesOf: a tile of 0 pixels");
    std::vector<PixelRect> tiles;
    for (uint32_t y = 0; y < height; y += tileSize)
        for (uint32_t x = 0; x < width; x += tileSize)
            tiles.push_back({x, y, std::min(width, x + tileSize), std::min(height, y + tileSize)});
    return tiles;
}

uint32_t tileSizeFor(uint32_t width, uint32_t height, int workers, uint32_t largest) {
    uint32_t size = largest;
    auto tiles = [&](uint32_t side) { return size_t((width + side - 1) / side) * ((height + side - 1) / side); };
    while (size > 16 && tiles(size) < 4 * size_t(workers)) size /= 2;
    return size;
}

std::vector<PixelRect> bandsOf(uint32_t width, uint32_t height, int streams) {
    if (streams < 1) throw std::invalid_argument("bandsOf: no streams");
    constexpr uint32_t kBlockRows = 16;
    std::vector<PixelRect> bands;
    if (width == 0) return bands;
    for (uint32_t y = 0; y < height;) {
        const uint32_t rows = std::max(kBlockRows, (height - y) / uint32_t(streams) / kBlockRows * kBlockRows);
        bands.push_back({0, y, width, std::min(height, y + rows)});
        y = bands.back().y1;
    }
    return bands;
}

} // namespace urbis
