#include "render/tile_renderers.h"

#include "cpu/cpu_renderer.h"

namespace urbis {

uint64_t CpuTileRenderer::renderTile(const PixelRect& tile, Film& film) {
    RenderCounters counters;
    renderCpu(scene_, camera_, settings_, samples_, tile, film, counters);
    return counters.rays;
}

uint64_t GpuTileRenderer::renderTile(const PixelRect& tile, Film& film) {
    return stream_.renderTile(camera_, settings_, samples_, tile, film, photons_);
}

} // namespace urbis
