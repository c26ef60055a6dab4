#include "viewer/view_renderer.h"

#include <cstdio>

namespace urbis {

ProgressiveRenderer::ProgressiveRenderer(const Scene& scene, IntegratorKind integrator, const std::string& deviceChoice,
                                         bool verbose)
    : scene_(scene), deviceChoice_(deviceChoice), verbose_(verbose), integrator_(integrator),
      renderer_(Renderer::make(scene, integrator, {deviceChoice, {}, 0, verbose, nullptr})) {
    if (verbose) std::fprintf(stderr, "urbis: viewing on %s (%s)\n", deviceName().c_str(), device().c_str());
}

ProgressiveRenderer::~ProgressiveRenderer() = default;

void ProgressiveRenderer::restart(const Camera& camera, const RenderSettings& settings, bool aovs) {
    if (settings.integrator != integrator_) {
        renderer_.reset();   // its device memory goes before the next one's is taken
        renderer_ = Renderer::make(scene_, settings.integrator, {deviceChoice_, {}, 0, verbose_, nullptr});
        integrator_ = settings.integrator;
    }
    camera_ = camera;
    settings_ = settings;
    settings_.spp = 1;
    film_ = Film(settings.width, settings.height, aovs);
    samples_ = 0;
    filmCurrent_ = true;
    renderer_->startFilm(film_);
}

void ProgressiveRenderer::addSample(RenderCounters& counters) {
    renderer_->addSamples(camera_, settings_, SampleRange{samples_, 1}, counters);
    filmCurrent_ = false;
    ++samples_;
}

const Film& ProgressiveRenderer::film() {
    if (!filmCurrent_) {
        renderer_->readFilm(film_);
        filmCurrent_ = true;
    }
    return film_;
}

void ProgressiveRenderer::makePicture(FilmDisplay display, float exposureEv, bool denoise, uint8_t* deviceRgba) {
    const bool denoised = denoise && samples_ > 0 && samples_ < kDenoiseUntil && film_.hasAovs();
    renderer_->drawPicture(display, exposureEv, denoised, deviceRgba);
}

} // namespace urbis
