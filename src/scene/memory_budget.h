// How much memory a build may take, checked before building large stored geometry (host).
#pragma once

#include <cstddef>

namespace urbis {

/// Peak bytes per stored triangle while a scene is built: the mesh (44), its copy in leaf order
/// (44), the builder's bounds, centroids, order and binary nodes (about 104) and the wide nodes
/// (about 40).
inline constexpr size_t kBuildBytesPerTriangle = 232;

/// MemAvailable of /proc/meminfo in bytes; 0 where it cannot be read.
size_t availableMemoryBytes();

} // namespace urbis
