// The AOV layer groups an EXR holds beside RGBA, by the names scene files give them (film.layers).
#pragma once

#include <cstdint>

namespace urbis {

/// Bit i of a layer mask stands for kFilmLayerNames[i].
inline constexpr const char* kFilmLayerNames[] = {"albedo", "normal", "depth", "position", "id", "samples"};
inline constexpr uint32_t kFilmLayerCount = sizeof(kFilmLayerNames) / sizeof(kFilmLayerNames[0]);
inline constexpr uint32_t kAllFilmLayers = (1u << kFilmLayerCount) - 1u;

enum FilmLayerBit : uint32_t {
    kAlbedoLayer = 1u << 0,
    kNormalLayer = 1u << 1,
    kDepthLayer = 1u << 2,
    kPositionLayer = 1u << 3,
    kIdLayer = 1u << 4,
    kSamplesLayer = 1u << 5,
};

} // namespace urbis
