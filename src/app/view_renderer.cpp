#include "app/view_renderer.h"

#include "app/render_device.h"
#include "base/input_error.h"
#include "cpu/cpu_denoiser.h"
#include "cpu/cpu_renderer.h"

#include <cstdio>
#include <stdexcept>

namespace urbis {

ProgressiveRenderer::ProgressiveRenderer(const Scene& scene, const std::string& device, bool verbose) : scene_(scene) {
    if (device != "cpu") {
        const GpuInfo info = probeGpu();
        if (!info.available && device == "cuda") throw InputError("--device cuda: " + info.reason, FailureKind::Device);
        if (info.available) {
            try {
                gpu_ = GpuScene::upload(scene);
                device_ = "cuda";
                deviceName_ = info.name;
            } catch (const InputError& e) {
                if (device == "cuda") throw;
                std::fprintf(stderr, "urbis: %s; falling back to the CPU\n", e.what());
            }
        } else if (verbose) {
            std::fprintf(stderr, "urbis: rendering on the CPU (%s)\n", info.reason.c_str());
        }
    }
    if (!gpu_) deviceName_ = cpuModelName();
    if (verbose) std::fprintf(stderr, "urbis: viewing on %s (%s)\n", deviceName_.c_str(), device_.c_str());
}

ProgressiveRenderer::~ProgressiveRenderer() = default;

void ProgressiveRenderer::restart(const Camera& camera, const RenderSettings& settings, bool aovs) {
    camera_ = camera;
    settings_ = settings;
    settings_.spp = 1;
    film_ = Film(settings.width, settings.height, aovs);
    samples_ = 0;
    filmCurrent_ = true;
    if (gpu_) gpu_->setFilm(film_);
}

void ProgressiveRenderer::addSample(RenderCounters& counters) {
    const SampleRange next{samples_, 1};
    if (gpu_) {
        gpu_->render(camera_, settings_, next, counters);
        filmCurrent_ = false;
    } else {
        renderCpu(scene_.view(), camera_, settings_, next, film_, false, counters);
    }
    ++samples_;
}

const Film& ProgressiveRenderer::film() {
    if (!filmCurrent_) {
        gpu_->readFilm(film_);
        filmCurrent_ = true;
    }
    return film_;
}

void ProgressiveRenderer::makePicture(FilmDisplay display, float exposureEv, bool denoise, uint8_t* deviceRgba) {
    const bool denoised = denoise && samples_ > 0 && samples_ < kDenoiseUntil && film_.hasAovs();
    if (gpu_) {
        gpu_->drawPicture(display, exposureEv, denoised, deviceRgba);
        return;
    }
    if (deviceRgba) throw std::invalid_argument("ProgressiveRenderer::makePicture: no device picture on the CPU");
    if (!denoised) {
        hostPicture_ = displayImage(film_, display, exposureEv);
        return;
    }
    Film copy = film_;  // the filter leaves no unbiased sums: the film goes on from the copy
    denoiseCpu(copy);
    hostPicture_ = displayImage(copy, display, exposureEv);
}

Rgb8Image ProgressiveRenderer::picture() const { return gpu_ ? gpu_->readPicture() : hostPicture_; }

size_t ProgressiveRenderer::deviceBytes() const { return gpu_ ? gpu_->memory().total() : 0; }

} // namespace urbis
