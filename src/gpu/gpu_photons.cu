// The photon passes' kernels and device memory; the per-ray code is integrators/photon_*.h, the
// same as the CPU's (cpu/cpu_photons.cpp).
#include "gpu/gpu_photons.h"

#include "gpu/cuda_check.h"
#include "gpu/device_buffer.h"
#include "gpu/device_event_timer.h"
#include "integrators/photon_blocks.h"
#include "integrators/photon_buffer_layout.h"
#include "integrators/photon_camera.h"
#include "integrators/photon_emission_setup.h"
#include "integrators/photon_trace.h"

#include <thrust/copy.h>
#include <thrust/device_ptr.h>
#include <thrust/execution_policy.h>
#include <thrust/sort.h>

#include <algorithm>
#include <bit>
#include <utility>

namespace urbis {

namespace {

constexpr int kPhotonBlock = 128;
constexpr int kTileX = 8, kTileY = 16;

uint32_t blocksFor(size_t count) { return uint32_t((count + kPhotonBlock - 1) / kPhotonBlock); }

void checkPhotonLaunch(const char* kernel) {
    cudaError_t status = cudaGetLastError();
    if (status != cudaSuccess)
        throw InputError(std::string("CUDA error launching ") + kernel + ": " + cudaGetErrorString(status), FailureKind::Device);
}

/// One thread per photon: traces it, storing into its slots (settings.maxDepth per photon).
template <bool CostlyLeaves>
__global__ void __launch_bounds__(kPhotonBlock) photonMapKernel(SceneView scene, RenderSettings settings, Photon* slots,
                                                                unsigned long long* rayCount) {
    scene.costlyLeaves = CostlyLeaves;
    scene.features = kAllFeatures;   // one kernel for any scene: its tests of the kinds fold away
    const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= settings.photonsPerPass) return;
    PhotonSlotSink sink{slots + size_t(i) * settings.maxDepth};
    const uint32_t rays = tracePhoton(scene, settings, i, sink);
    if (rays > 0) atomicAdd(rayCount, (unsigned long long)rays);
}

/// One thread per photon: traces it, splatting into the photon buffers.
template <bool CostlyLeaves>
__global__ void __launch_bounds__(kPhotonBlock) photonSplatKernel(SceneView scene, RenderSettings settings,
                                                                  unsigned long long* rayCount) {
    scene.costlyLeaves = CostlyLeaves;
    scene.features = kAllFeatures;   // one kernel for any scene: its tests of the kinds fold away
    const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= settings.photonsPerPass) return;
    PhotonSplatSink sink{scene.photons.buffers};
    const uint32_t rays = tracePhoton(scene, settings, i, sink);
    if (rays > 0) atomicAdd(rayCount, (unsigned long long)rays);
}

/// One thread per pixel (x, y): op(scene, settings, x, y), the leaves' cost trait fixed at compile time.
template <bool CostlyLeaves, typename PixelOp>
__global__ void __launch_bounds__(kTileX * kTileY) pixelKernel(SceneView scene, RenderSettings settings, PixelOp op) {
    scene.costlyLeaves = CostlyLeaves;
    scene.features = kAllFeatures;   // one kernel for any scene: its tests of the kinds fold away
    const uint32_t x = blockIdx.x * blockDim.x + threadIdx.x, y = blockIdx.y * blockDim.y + threadIdx.y;
    if (x >= settings.width || y >= settings.height) return;
    op(scene, settings, x, y);
}

/// Launches pixelKernel over the image of `settings`.
template <typename PixelOp>
void launchPerPixel(const SceneView& view, const RenderSettings& settings, const PixelOp& op, const char* name) {
    const dim3 block(kTileX, kTileY);
    const dim3 grid((settings.width + kTileX - 1) / kTileX, (settings.height + kTileY - 1) / kTileY);
    if (view.costlyLeaves) pixelKernel<true><<<grid, block>>>(view, settings, op);
    else pixelKernel<false><<<grid, block>>>(view, settings, op);
    checkPhotonLaunch(name);
}

/// The visibility flags: the block a pixel's camera chain of sample `sample` ends on is seen.
struct FlagSeenBlock {
    Camera camera;
    uint32_t sample;
    uint8_t* seen;
    __device__ void operator()(const SceneView& scene, const RenderSettings& settings, uint32_t x, uint32_t y) const {
        const uint32_t block = cameraSampleBlock(scene, camera, settings, x, y, sample);
        if (block != kNoBlock) seen[block] = 1;
    }
};

/// The lighting pass's first hits: the end of a pixel's camera chain of sample `sample`.
struct StoreChainEnd {
    Camera camera;
    uint32_t sample;
    CameraChainEnd* ends;
    __device__ void operator()(const SceneView& scene, const RenderSettings& settings, uint32_t x, uint32_t y) const {
        ends[size_t(y) * settings.width + x] = followCameraChain(scene, camera, settings, x, y, sample).end;
    }
};

/// One thread per pixel: the photons' indirect light at its chain's end (the lighting pass apart).
__global__ void __launch_bounds__(kPhotonBlock) lightingPassKernel(SceneView scene, IntegratorKind integrator,
                                                                   const CameraChainEnd* ends, uint32_t count, Vec3f* indirect) {
    const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= count) return;
    const CameraChainEnd& end = ends[i];
    indirect[i] = end.hit.valid() ? end.throughput * photonIndirect(scene, integrator, end.hit, end.wo) : Vec3f{};
}

/// One thread per stored photon: its bucket in the grid.
__global__ void photonBucketKernel(const Photon* photons, uint32_t count, float cellSize, uint32_t mask, uint32_t* keys) {
    const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= count) return;
    int x, y, z;
    photonCell(photons[i].position, cellSize, x, y, z);
    keys[i] = photonBucket(x, y, z, mask);
}

/// One thread per sorted photon: where its bucket's run starts and ends.
__global__ void photonRangeKernel(const uint32_t* keys, uint32_t count, uint32_t* start, uint32_t* end) {
    const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= count) return;
    if (i == 0 || keys[i] != keys[i - 1]) start[keys[i]] = i;
    if (i + 1 == count || keys[i] != keys[i + 1]) end[keys[i]] = i + 1;
}

struct HasPower {
    __host__ __device__ bool operator()(const Photon& p) const { return maxComponent(p.power) > 0.0f; }
};

} // namespace

struct GpuPhotonPasses::Impl {
    bool built = false;
    PhotonsView emission;
    PhotonBlockSet blocks;            // host copy: the allocation is decided on the host
    float fixedScale = 0;
    uint32_t passes = 0, texelCount = 0;
    bool flagged = false;             // the visibility flags, taken once per camera (newView)
    Camera flaggedCamera;
    DeviceBuffer<PhotonBlock> deviceBlocks;
    DeviceBuffer<uint32_t> blockOfObject, groundCells;
    DeviceBuffer<unsigned long long> texels;
    DeviceBuffer<uint8_t> seen;
    DeviceBuffer<Photon> slots, stored;
    DeviceBuffer<uint32_t> keys, cellStart, cellEnd;
    DeviceBuffer<unsigned long long> rayCount{1};

    PhotonBuffersView buffersView() {
        return {deviceBlocks.data(), uint32_t(deviceBlocks.size()), blockOfObject.data(), uint32_t(blockOfObject.size()),
                groundCells.data(), blocks.groundW, blocks.groundH, blocks.groundLo, blocks.groundCell,
                texels.size() ? texels.data() : nullptr, fixedScale};
    }

    /// Grows the texels to `count`, keeping the sums already splatted and zeroing the rest.
    void growTexels(uint32_t count) {
        if (size_t(count) * 3 <= texels.size()) return;
        DeviceBuffer<unsigned long long> grown(size_t(count) * 3);
        URBIS_CUDA_CHECK(cudaMemset(grown.data(), 0, grown.bytes()));
        if (texels.size())
            URBIS_CUDA_CHECK(cudaMemcpy(grown.data(), texels.data(), texels.bytes(), cudaMemcpyDeviceToDevice));
        std::swap(texels, grown);
    }
};

GpuPhotonPasses::GpuPhotonPasses(const Scene& scene, const GpuScene& gpu)
    : scene_(scene), gpu_(gpu), impl_(std::make_unique<Impl>()) {}
GpuPhotonPasses::~GpuPhotonPasses() = default;

size_t GpuPhotonPasses::bytes() const {
    const Impl& m = *impl_;
    return m.deviceBlocks.bytes() + m.blockOfObject.bytes() + m.groundCells.bytes() + m.texels.bytes() + m.seen.bytes() +
           m.slots.bytes() + m.stored.bytes() + m.keys.bytes() + m.cellStart.bytes() + m.cellEnd.bytes();
}

PhotonsView GpuPhotonPasses::runPass(const Camera& camera, const RenderSettings& settings, uint32_t sample,
                                     PhotonTimings& timings) {
    Impl& m = *impl_;
    const bool buffers = settings.integrator == IntegratorKind::PhotonBuffers;
    if (!m.built) {
        const SceneView hostView = scene_.view();
        m.emission = photonEmissionOf(scene_, hostView);
        if (buffers) {
            m.blocks = buildPhotonBlocks(scene_);
            m.fixedScale = photonFixedScale(hostView, m.emission, settings);
            m.blockOfObject.upload(m.blocks.blockOfObject);
            m.groundCells.upload(m.blocks.groundCells);
            m.deviceBlocks.upload(m.blocks.blocks);
            m.seen.resize(m.blocks.blocks.size());
        }
        m.built = true;
    }
    SceneView view = gpu_.deviceView();
    view.photons = m.emission;
    URBIS_CUDA_CHECK(cudaMemset(m.rayCount.data(), 0, sizeof(unsigned long long)));
    EventTimer timer;
    const uint32_t photonBlocks = blocksFor(settings.photonsPerPass);
    if (buffers) {
        timer.start();
        view.photons.pass = m.passes;
        view.photons.buffers = m.buffersView();
        if (m.seen.size() && newView(m.flagged, m.flaggedCamera, camera)) {
            URBIS_CUDA_CHECK(cudaMemset(m.seen.data(), 0, m.seen.bytes()));
            launchPerPixel(view, settings, FlagSeenBlock{camera, sample, m.seen.data()}, "the visibility flags");
            const std::vector<uint8_t> seen = m.seen.download();
            m.texelCount = allocateSeenBlocks(m.blocks.blocks, seen, camera.position, settings, m.passes, m.texelCount);
            m.deviceBlocks.upload(m.blocks.blocks);
            m.growTexels(m.texelCount);
        }
        view.photons.buffers = m.buffersView();
        timings.flags += timer.stopMs() * 1e-3;
        timer.start();
        if (view.costlyLeaves) photonSplatKernel<true><<<photonBlocks, kPhotonBlock>>>(view, settings, m.rayCount.data());
        else photonSplatKernel<false><<<photonBlocks, kPhotonBlock>>>(view, settings, m.rayCount.data());
        checkPhotonLaunch("photonSplatKernel");
        timings.photons += timer.stopMs() * 1e-3;
        ++m.passes;
        timings.texels = m.texelCount;
        timings.blocks = uint32_t(m.blocks.blocks.size());
        timings.blocksWithMemory = 0;
        for (const PhotonBlock& b : m.blocks.blocks) timings.blocksWithMemory += b.texelOffset != kNoTexels;
    } else {
        timer.start();
        view.photons.pass = sample;
        const size_t slotCount = size_t(settings.photonsPerPass) * settings.maxDepth;
        m.slots.resize(slotCount);
        URBIS_CUDA_CHECK(cudaMemset(m.slots.data(), 0, m.slots.bytes()));
        if (view.costlyLeaves) photonMapKernel<true><<<photonBlocks, kPhotonBlock>>>(view, settings, m.slots.data(), m.rayCount.data());
        else photonMapKernel<false><<<photonBlocks, kPhotonBlock>>>(view, settings, m.slots.data(), m.rayCount.data());
        checkPhotonLaunch("photonMapKernel");
        // Compaction keeps the slots' order (thrust's copy_if is stable): the same photons in the same order as the CPU's.
        m.stored.resize(slotCount);
        const Photon* end = thrust::copy_if(thrust::device, m.slots.data(), m.slots.data() + slotCount, m.stored.data(), HasPower{});
        const uint32_t count = uint32_t(end - m.stored.data());
        timings.photons += timer.stopMs() * 1e-3;
        timings.stored += count;
        timer.start();
        PhotonGridView& grid = view.photons.grid;
        const uint32_t buckets = std::bit_ceil(std::max<uint32_t>(1024, 2 * count));
        grid.tableMask = buckets - 1;
        grid.radius = photonRadiusAt(settings.photonRadius, settings.photonAlpha, sample);
        grid.cellSize = 2.0f * grid.radius;
        m.keys.resize(std::max<uint32_t>(count, 1));
        m.cellStart.resize(buckets);
        m.cellEnd.resize(buckets);
        URBIS_CUDA_CHECK(cudaMemset(m.cellStart.data(), 0, m.cellStart.bytes()));
        URBIS_CUDA_CHECK(cudaMemset(m.cellEnd.data(), 0, m.cellEnd.bytes()));
        if (count > 0) {
            photonBucketKernel<<<blocksFor(count), kPhotonBlock>>>(m.stored.data(), count, grid.cellSize, grid.tableMask, m.keys.data());
            checkPhotonLaunch("photonBucketKernel");
            // A stable sort by bucket: within a bucket the compacted order, as the CPU's counting sort.
            thrust::stable_sort_by_key(thrust::device, m.keys.data(), m.keys.data() + count, m.stored.data());
            photonRangeKernel<<<blocksFor(count), kPhotonBlock>>>(m.keys.data(), count, m.cellStart.data(), m.cellEnd.data());
            checkPhotonLaunch("photonRangeKernel");
        }
        grid.photons = m.stored.data();
        grid.cellStart = m.cellStart.data();
        grid.cellEnd = m.cellEnd.data();
        timings.grid += timer.stopMs() * 1e-3;
    }
    timings.photonRays += m.rayCount.download()[0];
    return view.photons;
}

double GpuPhotonPasses::timeLightingPass(const PhotonsView& photons, const Camera& camera, const RenderSettings& settings,
                                         uint32_t sample) {
    SceneView view = gpu_.deviceView();
    view.photons = photons;
    const uint32_t pixels = settings.width * settings.height;
    DeviceBuffer<CameraChainEnd> ends(pixels);
    DeviceBuffer<Vec3f> indirect(pixels);
    launchPerPixel(view, settings, StoreChainEnd{camera, sample, ends.data()}, "the lighting pass's first hits");
    EventTimer timer;
    timer.start();
    lightingPassKernel<<<blocksFor(pixels), kPhotonBlock>>>(view, settings.integrator, ends.data(), pixels, indirect.data());
    checkPhotonLaunch("lightingPassKernel");
    return timer.stopMs() * 1e-3;
}

} // namespace urbis
