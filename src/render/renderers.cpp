// The list of integrators' Renderers: the one place that maps an IntegratorKind to its Renderer.
#include "render/path_renderer.h"
#include "render/photon_renderer.h"

namespace urbis {

std::unique_ptr<Renderer> Renderer::make(const Scene& scene, IntegratorKind integrator, const RendererOptions& options) {
    switch (integrator) {
    case IntegratorKind::Path: return std::make_unique<PathRenderer>(scene, options);
    case IntegratorKind::PhotonBuffers:
    case IntegratorKind::PhotonMap: return std::make_unique<PhotonRenderer>(scene, options);
    }
    return std::make_unique<PathRenderer>(scene, options);
}

} // namespace urbis
