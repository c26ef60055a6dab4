// The two renderers of a frame's tiles (cluster/tile_renderer.h): the CPU's thread pool, and one GPU
// whose device film holds the frame while its tiles are rendered and copied back one by one. Each adds
// the samples of one round of its integrator, seen through what that round's light pass left.
#pragma once

#include "cluster/tile_renderer.h"
#include "gpu/gpu_backend.h"
#include "scene/camera.h"
#include "scene/render_settings.h"
#include "scene/scene_view.h"

namespace urbis {

/// Tiles by renderCpu on this process's threads, straight into the film it is given.
class CpuTileRenderer final : public TileRenderer {
public:
    /// `scene`: as the camera pass sees it (with the round's photons).
    CpuTileRenderer(const SceneView& scene, const Camera& camera, const RenderSettings& settings, SampleRange samples)
        : scene_(scene), camera_(camera), settings_(settings), samples_(samples) {}
    void startFrame(const Film&) override {}
    uint64_t renderTile(const PixelRect& tile, Film& film) override;

private:
    SceneView scene_;
    Camera camera_;
    RenderSettings settings_;
    SampleRange samples_;
};

/// Tiles on one GPU, on a CUDA stream of this renderer's own (GpuTileStream): several renderers of one
/// device, one host thread each, render its tiles at once. The device's first renderer (`makesFilm`)
/// makes the device film in startFrame, once a frame; each tile is one launch of the render kernels
/// over its pixels, then a copy of those pixels back to the host film.
class GpuTileRenderer final : public TileRenderer {
public:
    GpuTileRenderer(GpuScene& gpu, const Camera& camera, const RenderSettings& settings, SampleRange samples,
                    const PhotonsView& photons, bool makesFilm)
        : gpu_(gpu), stream_(gpu), camera_(camera), settings_(settings), samples_(samples), photons_(photons),
          makesFilm_(makesFilm) {}
    void startFrame(const Film& film) override {
        if (makesFilm_) gpu_.setFilm(film);
    }
    uint64_t renderTile(const PixelRect& tile, Film& film) override;

private:
    GpuScene& gpu_;
    GpuTileStream stream_;
    Camera camera_;
    RenderSettings settings_;
    SampleRange samples_;
    PhotonsView photons_;
    bool makesFilm_;
};

} // namespace urbis
