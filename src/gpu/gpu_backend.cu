// The CUDA backend: device memory and kernel launches only. Every kernel calls the shared
// URBIS_HD per-ray code (addPathSamples, addAovSamples, intersectScene, occludedScene) or per-pixel
// code (the denoiser's passes), the same as the CPU backend.
#include "gpu/gpu_backend.h"

#include "film/pixel_rect.h"
#include "gpu/cuda_check.h"
#include "gpu/device_buffer.h"
#include "gpu/device_event_timer.h"
#include "gpu/device_scene.h"
#include "gpu/gpu_photons.h"
#include "gpu/pinned_buffer.h"
#include "gpu/render_variants.h"
#include "integrators/aov_sample.h"
#include "integrators/path_samples.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <utility>

namespace urbis {

namespace {

constexpr int kTileX = 8, kTileY = 16;   // 128 threads; each warp covers 8 x 4 pixels
constexpr int kTraceBlock = 128;

// The render kernel is compiled once per set of kinds and features of gpu/render_variants.h: it
// fixes SceneView::features and costlyLeaves, so what its set leaves out (the traversal of costly
// leaves, a kind's intersector, the clouds' tracking, the planet's atmosphere, the photon camera
// pass) is not in it, and a scene runs the smallest that covers it. The batch kernels are compiled
// twice, with costly leaves and without. Blocks per SM that the render kernel's registers must
// allow: left free, ptxas took 158 registers for the inlined wall part tests, three blocks per SM.
// With costly leaves four (128 registers): the wall code spills least and fewer warps share the
// instruction cache. Without, five (102 registers): stored triangles ran 14 % slower at four.
template <bool CostlyLeaves>
constexpr int kRenderBlocksPerSm = CostlyLeaves ? 4 : 5;

/// One thread per pixel of `tile`: adds `samples` to the film, in sample order as on the CPU. The
/// scene holds nothing outside `Features` (renderVariantFor).
template <SceneFeatures Features>
__global__ void __launch_bounds__(kTileX * kTileY, kRenderBlocksPerSm<renderVariantHasCostlyLeaves(Features)>)
    renderKernel(SceneView scene, Camera camera, RenderSettings settings, SampleRange samples, PixelRect tile,
                 FilmView film, unsigned long long* rayCount) {
    // Constants from here on.
    scene.features = Features;
    scene.costlyLeaves = renderVariantHasCostlyLeaves(Features);
    if constexpr (!hasFeatures(Features, kPhotonsFeature)) settings.integrator = IntegratorKind::Path;
    const uint32_t x = tile.x0 + blockIdx.x * blockDim.x + threadIdx.x;
    const uint32_t y = tile.y0 + blockIdx.y * blockDim.y + threadIdx.y;
    uint32_t rays = 0;
    if (x < tile.x1 && y < tile.y1)
        rays = addPathSamples(scene, camera, settings, x, y, samples, film);
    // One atomic per warp.
    unsigned long long total = rays;
    for (int offset = 16; offset > 0; offset /= 2) total += __shfl_down_sync(0xffffffffu, total, offset);
    if ((threadIdx.x + threadIdx.y * blockDim.x) % 32 == 0 && total > 0) atomicAdd(rayCount, total);
}

/// Launches the render kernel of variant `variant` (an index into kRenderVariants).
template <uint32_t... V>
void launchRenderVariant(uint32_t variant, std::integer_sequence<uint32_t, V...>, dim3 grid, dim3 block,
                         const SceneView& scene, const Camera& camera, const RenderSettings& settings,
                         SampleRange samples, const PixelRect& tile, const FilmView& film, unsigned long long* rayCount,
                         cudaStream_t stream) {
    (void)((variant == V &&
            (renderKernel<kRenderVariants[V]><<<grid, block, 0, stream>>>(scene, camera, settings, samples, tile, film,
                                                                          rayCount),
             true)) ||
           ...);
}

/// One thread per pixel of `tile`: the AOV pass of `samples`, apart from the path tracer's kernel.
__global__ void __launch_bounds__(kTileX * kTileY) aovKernel(SceneView scene, Camera camera, RenderSettings settings,
                                                             SampleRange samples, PixelRect tile, FilmView film) {
    scene.features = kAllFeatures;   // one kernel for any scene: its tests of the kinds fold away
    const uint32_t x = tile.x0 + blockIdx.x * blockDim.x + threadIdx.x;
    const uint32_t y = tile.y0 + blockIdx.y * blockDim.y + threadIdx.y;
    if (x < tile.x1 && y < tile.y1) addAovSamples(scene, camera, settings, x, y, samples, film);
}

/// One thread per pixel: the denoiser's guide and starting signal.
__global__ void __launch_bounds__(kTileX * kTileY) denoisePrepareKernel(FilmView film, DenoiseGuide* guide,
                                                                        DenoiseSignal* signal) {
    const uint32_t x = blockIdx.x * blockDim.x + threadIdx.x;
    const uint32_t y = blockIdx.y * blockDim.y + threadIdx.y;
    if (x < film.width && y < film.height) prepareDenoise(film, x, y, guide[film.pixel(x, y)], signal[film.pixel(x, y)]);
}

/// One thread per pixel: one a-trous iteration, taps `step` pixels apart.
__global__ void __launch_bounds__(kTileX * kTileY) denoiseStepKernel(DenoiseBuffers buffers, int step,
                                                                     DenoiseParams params) {
    const uint32_t x = blockIdx.x * blockDim.x + threadIdx.x;
    const uint32_t y = blockIdx.y * blockDim.y + threadIdx.y;
    if (x < buffers.width && y < buffers.height)
        buffers.out[size_t(y) * buffers.width + x] = denoiseStep(buffers, x, y, step, params);
}

/// One thread per pixel: the filtered irradiance times albedo into the film's radiance sums.
__global__ void __launch_bounds__(kTileX * kTileY) denoiseFinishKernel(FilmView film, const DenoiseGuide* guide,
                                                                       const DenoiseSignal* signal) {
    const uint32_t x = blockIdx.x * blockDim.x + threadIdx.x;
    const uint32_t y = blockIdx.y * blockDim.y + threadIdx.y;
    if (x < film.width && y < film.height) finishDenoise(film, x, y, guide[film.pixel(x, y)], signal[film.pixel(x, y)]);
}

/// One thread per pixel: its picture's `channels` bytes (RGB, or RGBA with alpha 255).
__global__ void __launch_bounds__(kTileX * kTileY) pictureKernel(FilmView film, FilmDisplay display, float exposureScale,
                                                                 uint8_t* picture, uint32_t channels) {
    const uint32_t x = blockIdx.x * blockDim.x + threadIdx.x;
    const uint32_t y = blockIdx.y * blockDim.y + threadIdx.y;
    if (x >= film.width || y >= film.height) return;
    const size_t i = film.pixel(x, y);
    uint8_t* out = picture + i * channels;
    displayPixel(film, display, exposureScale, i, out);
    if (channels == 4) out[3] = 255;
}

template <bool CostlyLeaves>
__global__ void __launch_bounds__(kTraceBlock) closestKernel(SceneView scene, const Ray* rays, SurfaceHit* hits,
                                                            uint32_t count) {
    scene.costlyLeaves = CostlyLeaves;
    scene.features = kAllFeatures;   // one kernel for any scene: its tests of the kinds fold away
    const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i < count) hits[i] = intersectScene(scene, rays[i]);
}

template <bool CostlyLeaves>
__global__ void __launch_bounds__(kTraceBlock) occludedKernel(SceneView scene, const Ray* rays, uint8_t* blocked,
                                                             uint32_t count) {
    scene.costlyLeaves = CostlyLeaves;
    scene.features = kAllFeatures;   // one kernel for any scene: its tests of the kinds fold away
    const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i < count) blocked[i] = occludedScene(scene, rays[i]) ? 1 : 0;
}

/// Launches check the launch itself at once and the kernel's run at the next synchronisation.
void checkLaunch(const char* kernel) {
    cudaError_t status = cudaGetLastError();
    if (status != cudaSuccess)
        throw InputError(std::string("CUDA error launching ") + kernel + ": " + cudaGetErrorString(status), FailureKind::Device);
}

std::string formatMiB(size_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f MiB", double(bytes) / (1024.0 * 1024.0));
    return text;
}

uint32_t blocksFor(size_t count) { return uint32_t((count + kTraceBlock - 1) / kTraceBlock); }

} // namespace

int gpuDeviceCount() {
    int count = 0;
    if (cudaGetDeviceCount(&count) != cudaSuccess) {
        cudaGetLastError();   // clear the error so that later calls start clean
        return 0;
    }
    return count;
}

GpuInfo probeGpu(int device) {
    GpuInfo info;
    int count = 0;
    cudaError_t status = cudaGetDeviceCount(&count);
    if (status != cudaSuccess || count == 0) {
        info.reason = std::string("no CUDA device: ") + (status != cudaSuccess ? cudaGetErrorString(status) : "none found");
        cudaGetLastError();   // clear the error so that later calls start clean
        return info;
    }
    if (device < 0 || device >= count) {
        info.reason = "no CUDA device " + std::to_string(device) + " (this machine has " + std::to_string(count) + ")";
        return info;
    }
    cudaDeviceProp prop{};
    status = cudaGetDeviceProperties(&prop, device);
    if (status == cudaSuccess) status = cudaSetDevice(device);
    if (status == cudaSuccess) status = cudaMemGetInfo(&info.freeBytes, &info.totalBytes);
    if (status != cudaSuccess) {
        info.reason = std::string("no usable CUDA device: ") + cudaGetErrorString(status);
        return info;
    }
    info.name = prop.name;
    info.computeMajor = prop.major;
    info.computeMinor = prop.minor;
    info.multiprocessors = prop.multiProcessorCount;
    // The fat binary holds code for URBIS_CUDA_ARCHITECTURES only: ask whether a kernel loads here.
    cudaFuncAttributes attributes{};
    status = cudaFuncGetAttributes(&attributes, renderKernel<kAllFeatures>);
    if (status != cudaSuccess) {
        info.reason = "CUDA device " + info.name + " (sm_" + std::to_string(prop.major) + std::to_string(prop.minor) +
                      ") cannot run this build's kernels (" + cudaGetErrorString(status) +
                      "); rebuild with -DURBIS_CUDA_ARCHITECTURES=" + std::to_string(prop.major) +
                      std::to_string(prop.minor);
        cudaGetLastError();
        return info;
    }
    info.available = true;
    return info;
}

struct GpuScene::Impl {
    int device = 0;
    GpuInfo info;
    DeviceScene scene;
    FilmArrays<DeviceBuffer> film;
    uint32_t filmWidth = 0, filmHeight = 0;
    DeviceBuffer<Ray> rays;
    DeviceBuffer<SurfaceHit> hits;
    DeviceBuffer<uint8_t> blocked;
    DeviceBuffer<unsigned long long> rayCount{1};
    DeviceBuffer<uint8_t> picture;        ///< drawPicture's own RGB picture
    DeviceBuffer<Vec3f> radianceKept;     ///< the film's radiance sums while a denoised picture is made

    /// The device film's arrays as per-ray code sees them.
    FilmView filmView() {
        FilmView view{filmWidth, filmHeight};
        forEachFilmArray([&](auto member, bool, auto& buffer) { view.*member = buffer.size() ? buffer.data() : nullptr; },
                         film);
        return view;
    }
    size_t filmBytes() const {
        size_t bytes = 0;
        forEachFilmArray([&](auto, bool, const auto& buffer) { bytes += buffer.bytes(); }, film);
        return bytes;
    }

    /// Launches the path tracer, then the AOV pass where the film keeps AOVs, adding `samples` to
    /// the device film; returns after the launches (not the run). `photons`: what a photon
    /// integrator's camera pass sees of its photon pass.
    void launchRender(const Camera& camera, const RenderSettings& settings, SampleRange samples,
                      const PhotonsView& photons = {}) {
        launchRender(camera, settings, samples, PixelRect{0, 0, settings.width, settings.height}, rayCount.data(), nullptr,
                     photons);
    }
    /// launchRender of the pixels of `tile` only, on `stream`, counting rays into `rayCounter`.
    void launchRender(const Camera& camera, const RenderSettings& settings, SampleRange samples, const PixelRect& tile,
                      unsigned long long* rayCounter, cudaStream_t stream, const PhotonsView& photons = {}) {
        if (filmWidth != settings.width || filmHeight != settings.height)
            throw std::invalid_argument("GpuScene::render: the film's size is not the settings' image size");
        if (tile.x1 > filmWidth || tile.y1 > filmHeight || tile.x0 > tile.x1 || tile.y0 > tile.y1)
            throw std::invalid_argument("GpuScene::render: the tile is not inside the film");
        if (tile.pixels() == 0) return;
        dim3 block(kTileX, kTileY);
        dim3 grid((tile.width() + kTileX - 1) / kTileX, (tile.height() + kTileY - 1) / kTileY);
        SceneView view = scene.view();
        view.photons = photons;
        const FilmView target = filmView();
        const SceneFeatures features = view.features | (settings.integrator == IntegratorKind::Path ? 0 : kPhotonsFeature);
        launchRenderVariant(renderVariantFor(features), std::make_integer_sequence<uint32_t, kRenderVariantCount>{}, grid,
                            block, view, camera, settings, samples, tile, target, rayCounter, stream);
        checkLaunch("renderKernel");
        if (!target.hasAovs()) return;
        aovKernel<<<grid, block, 0, stream>>>(view, camera, settings, samples, tile, target);
        checkLaunch("aovKernel");
    }

    /// Launches closest-hit or any-hit tracing of the rays already in `rays`.
    void launchTrace(bool shadow) {
        const uint32_t n = uint32_t(rays.size());
        if (n == 0) return;
        if (shadow) {
            blocked.resize(n);
            const SceneView view = scene.view();
            if (view.costlyLeaves) occludedKernel<true><<<blocksFor(n), kTraceBlock>>>(view, rays.data(), blocked.data(), n);
            else occludedKernel<false><<<blocksFor(n), kTraceBlock>>>(view, rays.data(), blocked.data(), n);
            checkLaunch("occludedKernel");
        } else {
            hits.resize(n);
            const SceneView view = scene.view();
            if (view.costlyLeaves) closestKernel<true><<<blocksFor(n), kTraceBlock>>>(view, rays.data(), hits.data(), n);
            else closestKernel<false><<<blocksFor(n), kTraceBlock>>>(view, rays.data(), hits.data(), n);
            checkLaunch("closestKernel");
        }
    }

    /// Makes this GpuScene's device the calling thread's: CUDA keeps the current device per host thread.
    void use() const { URBIS_CUDA_CHECK(cudaSetDevice(device)); }

    /// Checks that `bytes` more fit in the free device memory.
    void requireFree(size_t bytes, const char* what) const {
        size_t freeBytes = 0, totalBytes = 0;
        URBIS_CUDA_CHECK(cudaMemGetInfo(&freeBytes, &totalBytes));
        if (bytes > freeBytes)
            throw InputError(std::string(what) + " needs " + formatMiB(bytes) + " of GPU memory but " + info.name +
                             " has " + formatMiB(freeBytes) + " free of " + formatMiB(totalBytes), FailureKind::OutOfMemory);
    }
};

GpuScene::GpuScene(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

GpuScene::~GpuScene() {
    if (cudaSetDevice(impl_->device) != cudaSuccess) cudaGetLastError();   // the buffers are freed on their device
}

std::unique_ptr<GpuScene> GpuScene::upload(const Scene& scene, size_t extraBytes, int device) {
    GpuInfo info = probeGpu(device);   // makes `device` current before Impl allocates its first buffer
    if (!info.available) throw InputError(info.reason, FailureKind::Device);
    auto impl = std::make_unique<Impl>();
    impl->device = device;
    impl->info = std::move(info);
    impl->requireFree(DeviceScene::bytesFor(scene) + extraBytes, "the scene");
    impl->scene.upload(scene);
    return std::unique_ptr<GpuScene>(new GpuScene(std::move(impl)));
}

void GpuScene::setFilm(const Film& host) {
    Impl& m = *impl_;
    m.use();
    const size_t needed = Film::bytesFor(host.width, host.height, host.hasAovs());
    m.requireFree(needed > m.filmBytes() ? needed - m.filmBytes() : 0, "the film");
    forEachFilmArray([](auto, bool, auto& device, const auto& array) { device.upload(array); }, m.film, host.arrays);
    m.filmWidth = host.width;
    m.filmHeight = host.height;
    URBIS_CUDA_CHECK(cudaDeviceSynchronize());   // the copies done, for tiles on non-blocking streams too
}

void GpuScene::render(const Camera& camera, const RenderSettings& settings, SampleRange samples,
                      RenderCounters& counters, const PhotonsView& photons) {
    Impl& m = *impl_;
    m.use();
    URBIS_CUDA_CHECK(cudaMemset(m.rayCount.data(), 0, sizeof(unsigned long long)));
    EventTimer timer;
    timer.start();
    m.launchRender(camera, settings, samples, photons);
    counters.seconds = timer.stopMs() * 1e-3;
    URBIS_CUDA_CHECK(cudaDeviceSynchronize());
    counters.rays = m.rayCount.download()[0];
}

void GpuScene::relight(const Scene& scene) {
    impl_->use();
    impl_->scene.uploadLighting(scene);
}

void GpuScene::denoise(const DenoiseParams& params) {
    Impl& m = *impl_;
    m.use();
    const FilmView film = m.filmView();
    if (!film.hasAovs()) throw std::invalid_argument("GpuScene::denoise: the film keeps no AOVs to guide the filter");
    const size_t pixels = size_t(film.width) * film.height;
    m.requireFree(pixels * kDenoiseBytesPerPixel, "the denoiser");
    // Held for this call only: a frame's guide and two signals, the iterations' ping-pong.
    DeviceBuffer<DenoiseGuide> guide(pixels);
    DeviceBuffer<DenoiseSignal> signal(pixels), next(pixels);
    const dim3 block(kTileX, kTileY);
    const dim3 grid((film.width + kTileX - 1) / kTileX, (film.height + kTileY - 1) / kTileY);
    denoisePrepareKernel<<<grid, block>>>(film, guide.data(), signal.data());
    checkLaunch("denoisePrepareKernel");
    for (uint32_t i = 0; i < params.iterations; ++i) {
        denoiseStepKernel<<<grid, block>>>(DenoiseBuffers{film.width, film.height, guide.data(), signal.data(), next.data()},
                                           1 << i, params);
        checkLaunch("denoiseStepKernel");
        std::swap(signal, next);
    }
    denoiseFinishKernel<<<grid, block>>>(film, guide.data(), signal.data());
    checkLaunch("denoiseFinishKernel");
    URBIS_CUDA_CHECK(cudaDeviceSynchronize());
}

void GpuScene::readFilm(Film& host) const {
    const Impl& m = *impl_;
    m.use();
    host.width = m.filmWidth;
    host.height = m.filmHeight;
    forEachFilmArray([](auto, bool, const auto& device, auto& array) { array = device.download(); }, m.film, host.arrays);
}

void GpuScene::drawPicture(FilmDisplay display, float exposureEv, bool denoised, uint8_t* rgba) {
    Impl& m = *impl_;
    m.use();
    const FilmView film = m.filmView();
    const size_t pixels = size_t(film.width) * film.height;
    if (display != FilmDisplay::Image && !film.hasAovs())
        throw std::invalid_argument("GpuScene::drawPicture: the film keeps no AOVs to show");
    if (denoised) {   // the filter overwrites the radiance sums only: they are kept aside, then put back
        m.radianceKept.resize(pixels);
        URBIS_CUDA_CHECK(cudaMemcpy(m.radianceKept.data(), film.radianceSum, pixels * sizeof(Vec3f), cudaMemcpyDeviceToDevice));
        denoise();
    }
    const uint32_t channels = rgba ? 4 : 3;
    if (!rgba) {
        m.picture.resize(pixels * channels);
        rgba = m.picture.data();
    }
    const dim3 block(kTileX, kTileY);
    const dim3 grid((film.width + kTileX - 1) / kTileX, (film.height + kTileY - 1) / kTileY);
    pictureKernel<<<grid, block>>>(film, display, std::exp2(exposureEv), rgba, channels);
    checkLaunch("pictureKernel");
    if (denoised)
        URBIS_CUDA_CHECK(cudaMemcpy(film.radianceSum, m.radianceKept.data(), pixels * sizeof(Vec3f), cudaMemcpyDeviceToDevice));
    URBIS_CUDA_CHECK(cudaDeviceSynchronize());
}

Rgb8Image GpuScene::readPicture() const {
    const Impl& m = *impl_;
    m.use();
    return {m.filmWidth, m.filmHeight, m.picture.download()};
}

LinearImage GpuScene::render(const Camera& camera, const RenderSettings& settings, RenderCounters& counters) {
    Film film(settings.width, settings.height, false);
    setFilm(film);
    render(camera, settings, SampleRange{0, settings.spp}, counters);
    readFilm(film);
    return meanRadiance(film);
}

std::vector<SurfaceHit> GpuScene::intersect(const std::vector<Ray>& rays) {
    impl_->use();
    impl_->rays.upload(rays);
    impl_->launchTrace(false);
    URBIS_CUDA_CHECK(cudaDeviceSynchronize());
    return rays.empty() ? std::vector<SurfaceHit>{} : impl_->hits.download();
}

std::vector<uint8_t> GpuScene::occluded(const std::vector<Ray>& rays) {
    impl_->use();
    impl_->rays.upload(rays);
    impl_->launchTrace(true);
    URBIS_CUDA_CHECK(cudaDeviceSynchronize());
    return rays.empty() ? std::vector<uint8_t>{} : impl_->blocked.download();
}

std::vector<float> GpuScene::timeTrace(const std::vector<Ray>& rays, bool shadow, int warmup, int repeats) {
    Impl& m = *impl_;
    m.use();
    m.requireFree(rays.size() * (sizeof(Ray) + sizeof(SurfaceHit)), "the ray batch");
    m.rays.upload(rays);
    for (int i = 0; i < warmup; ++i) m.launchTrace(shadow);
    URBIS_CUDA_CHECK(cudaDeviceSynchronize());
    std::vector<float> ms;
    EventTimer timer;
    for (int i = 0; i < repeats; ++i) {
        timer.start();
        m.launchTrace(shadow);
        ms.push_back(timer.stopMs());
    }
    return ms;
}

std::unique_ptr<PhotonPasses> GpuScene::photonPasses(const Scene& scene) {
    impl_->use();   // its buffers are allocated on this device
    return std::make_unique<GpuPhotonPasses>(scene, *this);
}

SceneView GpuScene::deviceView() const {
    impl_->use();
    return impl_->scene.view();
}

GpuMemory GpuScene::memory() const {
    const Impl& m = *impl_;
    GpuMemory out;
    out.scene = m.scene.memory();
    out.film = m.filmBytes() + m.picture.bytes() + m.radianceKept.bytes();
    out.rays = m.rays.bytes() + m.hits.bytes() + m.blocked.bytes() + m.rayCount.bytes();
    return out;
}

const GpuInfo& GpuScene::info() const { return impl_->info; }

struct GpuTileStream::Impl {
    GpuScene::Impl& gpu;
    cudaStream_t stream = nullptr;
    DeviceBuffer<unsigned long long> rayCount{1};
    PinnedBuffer staging;   ///< the tile's ray count, then its pixels of every film array, one after the other

    explicit Impl(GpuScene::Impl& scene) : gpu(scene) {
        gpu.use();
        // Non-blocking: the legacy stream's work (other threads' setFilm, say) does not hold this one's tiles.
        URBIS_CUDA_CHECK(cudaStreamCreateWithFlags(&stream, cudaStreamNonBlocking));
    }
    ~Impl() {
        if (cudaSetDevice(gpu.device) == cudaSuccess && stream) cudaStreamDestroy(stream);
        cudaGetLastError();   // errors here are sticky ones already reported by the failing call
    }
};

GpuTileStream::GpuTileStream(GpuScene& gpu) : impl_(std::make_unique<Impl>(*gpu.impl_)) {}
GpuTileStream::~GpuTileStream() = default;
GpuTileStream::GpuTileStream(GpuTileStream&&) noexcept = default;

uint64_t GpuTileStream::renderTile(const Camera& camera, const RenderSettings& settings, SampleRange samples,
                                   const PixelRect& tile, Film& host, const PhotonsView& photons) {
    Impl& s = *impl_;
    GpuScene::Impl& m = s.gpu;
    m.use();
    if (host.width != m.filmWidth || host.height != m.filmHeight || host.hasAovs() != (m.film.albedoSum.size() > 0))
        throw std::invalid_argument("GpuTileStream::renderTile: the host film is not the device film's size and layers");
    URBIS_CUDA_CHECK(cudaMemsetAsync(s.rayCount.data(), 0, sizeof(unsigned long long), s.stream));
    m.launchRender(camera, settings, samples, tile, s.rayCount.data(), s.stream, photons);
    if (tile.pixels() == 0) return 0;
    // The device's copies go to the pinned staging, so that they queue on the stream behind the kernels
    // and the host thread waits for this stream alone; then the host puts the rows in place.
    size_t bytes = sizeof(unsigned long long);
    forEachFilmArray([&](auto, bool, const auto& array) { bytes += array.empty() ? 0 : tile.pixels() * sizeof(array[0]); },
                     host.arrays);
    s.staging.reserve(bytes);
    URBIS_CUDA_CHECK(cudaMemcpyAsync(s.staging.data(), s.rayCount.data(), sizeof(unsigned long long), cudaMemcpyDeviceToHost,
                                     s.stream));
    const size_t first = size_t(tile.y0) * m.filmWidth + tile.x0;
    size_t offset = sizeof(unsigned long long);
    forEachFilmArray(
        [&](auto, bool, const auto& device, const auto& array) {
            if (array.empty()) return;
            const size_t element = sizeof(array[0]), row = tile.width() * element;
            URBIS_CUDA_CHECK(cudaMemcpy2DAsync(s.staging.data() + offset, row, device.data() + first, m.filmWidth * element,
                                               row, tile.height(), cudaMemcpyDeviceToHost, s.stream));
            offset += tile.pixels() * element;
        },
        m.film, host.arrays);
    URBIS_CUDA_CHECK(cudaStreamSynchronize(s.stream));
    offset = sizeof(unsigned long long);
    forEachFilmArray(
        [&](auto, bool, auto& array) {
            if (array.empty()) return;
            const size_t element = sizeof(array[0]), row = tile.width() * element;
            for (uint32_t y = 0; y < tile.height(); ++y)
                std::memcpy(reinterpret_cast<uint8_t*>(array.data() + first + size_t(y) * m.filmWidth),
                            s.staging.data() + offset + y * row, row);
            offset += tile.pixels() * element;
        },
        host.arrays);
    unsigned long long rays = 0;
    std::memcpy(&rays, s.staging.data(), sizeof rays);
    return rays;
}

} // namespace urbis
