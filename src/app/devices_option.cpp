#include "app/devices_option.h"

#include "base/input_error.h"
#include "cluster/device_list.h"
#include "gpu/gpu_backend.h"

namespace urbis {

std::vector<int> devicesOf(const std::string& devices, const std::string& device) {
    if (devices.empty()) return {};
    if (device == "cpu") throw InputError("--devices " + devices + ": not with --device cpu (the devices are GPUs)", FailureKind::Usage);
    const int count = gpuDeviceCount();
    try {
        return parseDeviceList(devices, count);   // a list that does not parse is said first
    } catch (const InputError& e) {
        if (count > 0 || e.kind() != FailureKind::Device) throw;
        // Why there is none: "urbis was built without CUDA", "no CUDA device: <the driver's error>".
        throw InputError("--devices " + devices + ": " + probeGpu().reason, FailureKind::Device);
    }
}

} // namespace urbis
