#include "integrators/photon_buffer_layout.h"

#include "base/input_error.h"
#include "math/bounds.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace urbis {

uint32_t photonBufferLevel(float distance, float levelDistance) {
    if (!(distance > levelDistance)) return 0;
    return std::min(kPhotonLevels - 1, uint32_t(std::floor(std::log2(distance / levelDistance))) + 1);
}

void layOutPhotonBlock(PhotonBlock& block, uint32_t level, float texel0, uint32_t texelOffset, uint32_t pass) {
    const float texel = texel0 * float(1u << level);
    auto texels = [&](float length, uint32_t least) {
        return std::clamp(uint32_t(std::ceil(length / texel)), least, 4096u);
    };
    block.facadeX = texels(block.hi.x - block.lo.x, 1);
    block.facadeZ = texels(block.hi.z - block.lo.z, 1);
    block.facadeV = texels(block.hi.y - block.lo.y, 1);
    block.topU = texels(block.groundHi.x - block.groundLo.x, 1);
    block.topV = texels(block.groundHi.y - block.groundLo.y, 1);
    block.level = level;
    block.texelOffset = texelOffset;
    block.firstPass = pass;
}

uint32_t allocateSeenBlocks(std::vector<PhotonBlock>& blocks, const std::vector<uint8_t>& seen, Vec3f eye,
                            const RenderSettings& settings, uint32_t pass, uint32_t texelCount) {
    uint64_t count = texelCount;
    for (size_t k = 0; k < blocks.size(); ++k) {
        PhotonBlock& block = blocks[k];
        if (!seen[k] || block.texelOffset != kNoTexels) continue;
        const Vec3f nearest = vmin(vmax(eye, block.lo), block.hi);
        layOutPhotonBlock(block, photonBufferLevel(length(nearest - eye), settings.photonLevelDistance),
                          settings.photonTexel, uint32_t(count), pass);
        count += block.texels();
        if (count >= kNoTexels)
            throw InputError("the photon buffers need more than 2^32 texels: raise photons.texel", FailureKind::OutOfMemory);
    }
    return uint32_t(count);
}

bool newView(bool& flagged, Camera& flaggedCamera, const Camera& camera) {
    if (flagged && std::memcmp(&flaggedCamera, &camera, sizeof(Camera)) == 0) return false;
    flagged = true;
    flaggedCamera = camera;
    return true;
}

} // namespace urbis
