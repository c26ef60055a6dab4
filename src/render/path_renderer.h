// The path tracer's Renderer (integrators/path_tracer.h): no light pass, so a render is one round of
// camera passes and nothing persists between calls.
#pragma once

#include "render/renderer.h"

namespace urbis {

class PathRenderer final : public Renderer {
public:
    PathRenderer(const Scene& scene, const RendererOptions& options) : Renderer(scene, options) {}

private:
    bool hasLightPass() const override { return false; }
    PhotonsView lightPass(size_t, const Camera&, const RenderSettings&, uint32_t, PhotonTimings&) override { return {}; }
    std::optional<PhotonTimings> reportPasses(const Camera&, const RenderSettings&, uint32_t, const PhotonsView&,
                                              PhotonTimings) override {
        return std::nullopt;
    }
    void forgetState() override {}
    size_t stateBytes() const override { return 0; }
};

} // namespace urbis
