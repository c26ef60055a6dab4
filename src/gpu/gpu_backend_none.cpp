// The GPU backend of a build without CUDA: every entry point says so (the build uses this file
// instead of gpu_backend.cu when CMake finds no nvcc).
#include "gpu/gpu_backend.h"

#include "base/input_error.h"

namespace urbis {

namespace {
const char* const kNoCuda = "urbis was built without CUDA";
[[noreturn]] void noCuda() { throw InputError(kNoCuda, FailureKind::Device); }
} // namespace

GpuInfo probeGpu(int) {
    GpuInfo info;
    info.reason = kNoCuda;
    return info;
}

int gpuDeviceCount() { return 0; }

struct GpuScene::Impl {
    GpuInfo info;
};

GpuScene::GpuScene(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
GpuScene::~GpuScene() = default;
std::unique_ptr<GpuScene> GpuScene::upload(const Scene&, size_t, int) { noCuda(); }
void GpuScene::setFilm(const Film&) { noCuda(); }
void GpuScene::render(const Camera&, const RenderSettings&, SampleRange, RenderCounters&, const PhotonsView&) { noCuda(); }
void GpuScene::relight(const Scene&) { noCuda(); }
void GpuScene::denoise(const DenoiseParams&) { noCuda(); }
void GpuScene::readFilm(Film&) const { noCuda(); }
void GpuScene::drawPicture(FilmDisplay, float, bool, uint8_t*) { noCuda(); }
Rgb8Image GpuScene::readPicture() const { noCuda(); }
LinearImage GpuScene::render(const Camera&, const RenderSettings&, RenderCounters&) { noCuda(); }
std::unique_ptr<PhotonPasses> GpuScene::photonPasses(const Scene&) { noCuda(); }
SceneView GpuScene::deviceView() const { noCuda(); }
std::vector<SurfaceHit> GpuScene::intersect(const std::vector<Ray>&) { noCuda(); }
std::vector<uint8_t> GpuScene::occluded(const std::vector<Ray>&) { noCuda(); }
std::vector<float> GpuScene::timeTrace(const std::vector<Ray>&, bool, int, int) { noCuda(); }
GpuMemory GpuScene::memory() const { return {}; }
const GpuInfo& GpuScene::info() const { return impl_->info; }

struct GpuTileStream::Impl {};
GpuTileStream::GpuTileStream(GpuScene&) { noCuda(); }
GpuTileStream::~GpuTileStream() = default;
GpuTileStream::GpuTileStream(GpuTileStream&&) noexcept = default;
uint64_t GpuTileStream::renderTile(const Camera&, const RenderSettings&, SampleRange, const PixelRect&, Film&, const PhotonsView&) {
    noCuda();
}

} // namespace urbis
