// One GPU as a RenderDevice: the scene uploaded once (GpuScene), a device film that stays there
// between passes, tiles on CUDA streams of their own (GpuTileStream).
#pragma once

#include "cluster/tile_grid.h"
#include "render/render_device.h"

namespace urbis {

class GpuDevice final : public RenderDevice {
public:
    /// Uploads `scene` to CUDA device `device`, with room checked for `extraBytes` more (the film);
    /// throws InputError where it cannot.
    GpuDevice(const Scene& scene, size_t extraBytes, int device);

    const char* kind() const override { return "cuda"; }
    const std::string& name() const override { return gpu_->info().name; }
    void setFilm(Film& film) override { gpu_->setFilm(film); }
    void cameraPass(const Camera& camera, const RenderSettings& settings, SampleRange samples, const PhotonsView& photons,
                    bool showProgress, RenderCounters& counters) override;
    std::vector<std::unique_ptr<TileRenderer>> tileRenderers(const Camera& camera, const RenderSettings& settings,
                                                             SampleRange samples, const PhotonsView& photons,
                                                             int count) override;
    int tileStreams() const override { return kGpuStreamsPerDevice; }
    void denoise() override { gpu_->denoise(); }
    void readFilm(Film& film) override { gpu_->readFilm(film); }
    void drawPicture(FilmDisplay display, float exposureEv, bool denoised, uint8_t* deviceRgba) override {
        gpu_->drawPicture(display, exposureEv, denoised, deviceRgba);
    }
    Rgb8Image picture() const override { return gpu_->readPicture(); }
    std::unique_ptr<PhotonPasses> photonPasses(const Scene& scene) override { return gpu_->photonPasses(scene); }
    void relight(const Scene& scene) override { gpu_->relight(scene); }
    std::vector<float> timeTrace(const std::vector<Ray>& rays, bool shadow, int warmup, int repeats) override {
        return gpu_->timeTrace(rays, shadow, warmup, repeats);
    }
    GpuMemory memory() const override { return gpu_->memory(); }

private:
    std::unique_ptr<GpuScene> gpu_;
};

} // namespace urbis
