// The CPU as a RenderDevice: renderCpu's tiles over TBB's thread pool, straight into the host film.
#pragma once

#include "render/render_device.h"

namespace urbis {

class CpuDevice final : public RenderDevice {
public:
    /// Renders `scene` (which must outlive this).
    explicit CpuDevice(const Scene& scene);

    const char* kind() const override { return "cpu"; }
    const std::string& name() const override { return name_; }
    void setFilm(Film& film) override { film_ = &film; }
    void cameraPass(const Camera& camera, const RenderSettings& settings, SampleRange samples, const PhotonsView& photons,
                    bool showProgress, RenderCounters& counters) override;
    std::vector<std::unique_ptr<TileRenderer>> tileRenderers(const Camera& camera, const RenderSettings& settings,
                                                             SampleRange samples, const PhotonsView& photons,
                                                             int count) override;
    int tileStreams() const override { return 1; }
    void denoise() override;
    void readFilm(Film& film) override;
    void drawPicture(FilmDisplay display, float exposureEv, bool denoised, uint8_t* deviceRgba) override;
    Rgb8Image picture() const override { return picture_; }
    std::unique_ptr<PhotonPasses> photonPasses(const Scene& scene) override;
    void relight(const Scene&) override {}   // the passes read the host scene as it is
    std::vector<float> timeTrace(const std::vector<Ray>& rays, bool shadow, int warmup, int repeats) override;
    GpuMemory memory() const override { return {}; }

private:
    /// The scene as the camera pass sees it: with `photons`.
    SceneView viewWith(const PhotonsView& photons) const;

    const Scene& scene_;
    std::string name_;
    Film* film_ = nullptr;
    Rgb8Image picture_;
};

/// The CPU's model name from /proc/cpuinfo, or "cpu" where unknown.
std::string cpuModelName();

} // namespace urbis
