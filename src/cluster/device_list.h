// `--devices all|0,1,...`: which CUDA devices one process spreads its tiles and frames over.
#pragma once

#include <string>
#include <vector>

namespace urbis {

/// The CUDA device indices `text` names on a machine of `count` devices: "all" (0..count-1) or a
/// comma list of indices in its order ("0,2"), repeats allowed ("0,0": two GpuScenes on one GPU, as
/// the tests run on a machine of one). Throws InputError: usage where the text does not parse
/// ("--devices 0,x: ..."), device where an index is not a device here ("no CUDA device 3: this
/// machine has 2 (0-1)") or `count` is 0.
std::vector<int> parseDeviceList(const std::string& text, int count);

} // namespace urbis
