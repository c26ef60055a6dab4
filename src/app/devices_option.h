// `--devices all|0,1,...`: the CUDA devices one process renders on, checked before any work.
#pragma once

#include <string>
#include <vector>

namespace urbis {

/// The CUDA devices of `--devices` (`devices`; empty without it): refused with `--device cpu` (usage);
/// "built without CUDA", no device or an index this machine lacks (device).
std::vector<int> devicesOf(const std::string& devices, const std::string& device);

} // namespace urbis
