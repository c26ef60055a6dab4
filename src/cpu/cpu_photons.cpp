#include "cpu/cpu_photons.h"

#include "base/step_timer.h"
#include "integrators/photon_buffer_layout.h"
#include "integrators/photon_camera.h"
#include "integrators/photon_emission_setup.h"
#include "integrators/photon_trace.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <atomic>
#include <bit>

namespace urbis {

namespace {

/// Traces the pass's photons, handing each one's stores to sinkOf(photon index); returns the rays.
template <typename SinkOf>
uint64_t tracePhotonsCpu(const SceneView& view, const RenderSettings& settings, SinkOf sinkOf) {
    return tbb::parallel_reduce(
        tbb::blocked_range<uint32_t>(0, settings.photonsPerPass, 256), uint64_t(0),
        [&](const tbb::blocked_range<uint32_t>& range, uint64_t rays) {
            for (uint32_t i = range.begin(); i < range.end(); ++i) {
                auto sink = sinkOf(i);
                rays += tracePhoton(view, settings, i, sink);
            }
            return rays;
        },
        [](uint64_t a, uint64_t b) { return a + b; });
}

/// The visibility flags: which blocks the camera chains of sample `sample` end on.
std::vector<uint8_t> seenBlocksCpu(const SceneView& view, const Camera& camera, const RenderSettings& settings,
                                   uint32_t sample, size_t blocks) {
    std::vector<uint8_t> seen(blocks, 0);
    tbb::parallel_for(uint32_t(0), settings.height, [&](uint32_t y) {
        for (uint32_t x = 0; x < settings.width; ++x) {
            const uint32_t block = cameraSampleBlock(view, camera, settings, x, y, sample);
            if (block != kNoBlock) __atomic_store_n(&seen[block], uint8_t(1), __ATOMIC_RELAXED);
        }
    });
    return seen;
}

/// One lighting pass apart (PhotonTimings::lightingPass) on the photons of `view`: the camera chains of
/// sample `sample` to their ends first, then, timed, the photons' indirect light at every end; seconds.
double timeLightingPassCpu(const SceneView& view, const Camera& camera, const RenderSettings& settings, uint32_t sample) {
    const size_t pixels = size_t(settings.width) * settings.height;
    std::vector<CameraChainEnd> ends(pixels);
    tbb::parallel_for(uint32_t(0), settings.height, [&](uint32_t y) {
        for (uint32_t x = 0; x < settings.width; ++x)
            ends[size_t(y) * settings.width + x] = followCameraChain(view, camera, settings, x, y, sample).end;
    });
    std::vector<Vec3f> indirect(pixels);
    const auto t = SteadyClock::now();
    tbb::parallel_for(tbb::blocked_range<size_t>(0, pixels, 1024), [&](const tbb::blocked_range<size_t>& range) {
        for (size_t i = range.begin(); i < range.end(); ++i)
            if (ends[i].hit.valid()) indirect[i] = ends[i].throughput * photonIndirect(view, settings.integrator, ends[i].hit, ends[i].wo);
    });
    return secondsSince(t);
}

} // namespace

PhotonGridView buildPhotonGridCpu(const std::vector<Photon>& photons, float radius, std::vector<Photon>& sorted,
                                  std::vector<uint32_t>& start, std::vector<uint32_t>& end) {
    const uint32_t buckets = std::bit_ceil(std::max<uint32_t>(1024, uint32_t(2 * photons.size())));
    PhotonGridView grid;
    grid.tableMask = buckets - 1;
    grid.radius = radius;
    grid.cellSize = 2.0f * radius;
    std::vector<uint32_t> bucketOf(photons.size());
    start.assign(buckets, 0);
    for (size_t i = 0; i < photons.size(); ++i) {
        int x, y, z;
        photonCell(photons[i].position, grid.cellSize, x, y, z);
        bucketOf[i] = photonBucket(x, y, z, grid.tableMask);
        ++start[bucketOf[i]];
    }
    uint32_t sum = 0;
    for (uint32_t& s : start) {
        const uint32_t count = s;
        s = sum;
        sum += count;
    }
    end = start;
    sorted.resize(photons.size());
    for (size_t i = 0; i < photons.size(); ++i) sorted[end[bucketOf[i]]++] = photons[i];
    grid.photons = sorted.data();
    grid.cellStart = start.data();
    grid.cellEnd = end.data();
    return grid;
}

CpuPhotonPasses::CpuPhotonPasses(const Scene& scene) : scene_(scene), view_(scene.view()) {
    view_.photons = photonEmissionOf(scene, view_);
}

PhotonsView CpuPhotonPasses::runPass(const Camera& camera, const RenderSettings& settings, uint32_t sample,
                                     PhotonTimings& timings) {
    SceneView view = view_;
    auto t = SteadyClock::now();
    if (settings.integrator == IntegratorKind::PhotonBuffers) {
        if (!state_.built) {
            state_.blocks = buildPhotonBlocks(scene_);
            state_.fixedScale = photonFixedScale(view_, view_.photons, settings);
            state_.built = true;
        }
        // Visibility flags, then memory for the blocks seen for the first time; then the splats.
        view.photons.pass = state_.passes;
        PhotonBuffersView& b = view.photons.buffers;
        PhotonBlockSet& blocks = state_.blocks;
        b = {blocks.blocks.data(), uint32_t(blocks.blocks.size()), blocks.blockOfObject.data(),
             uint32_t(blocks.blockOfObject.size()), blocks.groundCells.data(), blocks.groundW, blocks.groundH,
             blocks.groundLo, blocks.groundCell, nullptr, state_.fixedScale};
        if (newView(state_.flagged, state_.flaggedCamera, camera)) {
            const std::vector<uint8_t> seen = seenBlocksCpu(view, camera, settings, sample, blocks.blocks.size());
            const uint32_t texels = allocateSeenBlocks(blocks.blocks, seen, camera.position, settings, state_.passes,
                                                       uint32_t(state_.texels.size() / 3));
            state_.texels.resize(size_t(texels) * 3, 0);
        }
        b.texels = state_.texels.data();
        timings.flags += secondsSince(t);
        t = SteadyClock::now();
        timings.photonRays += tracePhotonsCpu(view, settings, [&](uint32_t) { return PhotonSplatSink{b}; });
        ++state_.passes;
        timings.photons += secondsSince(t);
        timings.texels = state_.texels.size() / 3;
        timings.blocks = uint32_t(blocks.blocks.size());
        timings.blocksWithMemory = 0;
        for (const PhotonBlock& block : blocks.blocks) timings.blocksWithMemory += block.texelOffset != kNoTexels;
    } else {
        view.photons.pass = sample;
        const uint32_t perPhoton = settings.maxDepth;
        slots_.assign(size_t(settings.photonsPerPass) * perPhoton, Photon{});
        timings.photonRays += tracePhotonsCpu(view, settings, [&](uint32_t i) {
            return PhotonSlotSink{slots_.data() + size_t(i) * perPhoton};
        });
        stored_.clear();
        for (const Photon& p : slots_)
            if (maxComponent(p.power) > 0.0f) stored_.push_back(p);
        timings.stored += stored_.size();
        timings.photons += secondsSince(t);
        t = SteadyClock::now();
        view.photons.grid = buildPhotonGridCpu(stored_, photonRadiusAt(settings.photonRadius, settings.photonAlpha, sample),
                                               sorted_, start_, end_);
        timings.grid += secondsSince(t);
    }
    return view.photons;
}

double CpuPhotonPasses::timeLightingPass(const PhotonsView& photons, const Camera& camera, const RenderSettings& settings,
                                         uint32_t sample) {
    SceneView view = view_;
    view.photons = photons;
    return timeLightingPassCpu(view, camera, settings, sample);
}

size_t CpuPhotonPasses::bytes() const {
    return state_.texels.size() * sizeof(unsigned long long) + (slots_.capacity() + stored_.capacity() + sorted_.capacity()) * sizeof(Photon) +
           (start_.capacity() + end_.capacity()) * sizeof(uint32_t);
}

} // namespace urbis
