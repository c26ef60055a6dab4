#include "app/tile_renderers.h"

#include "cpu/cpu_renderer.h"

namespace urbis {

uint64_t CpuTileRenderer::renderTile(const PixelRect& tile, Film& film) {
    RenderCounters counters;
    renderCpu(scene_, camera_, settings_, samples_, tile, film, counters);
    return counters.rays;
}

uint64_t GpuTileRenderer::renderTile(const PixelRect& tile, Film& film) {
    RenderCounters counters;
    gpu_.render(camera_, settings_, samples_, tile, counters);
    gpu_.readFilm(tile, film);
    return counters.rays;
}

} // namespace urbis
