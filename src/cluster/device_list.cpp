#include "cluster/device_list.h"

#include "base/input_error.h"

#include <charconv>
#include <sstream>

namespace urbis {

namespace {

std::string devicesHere(int count) {
    return count == 1 ? "1 (0)" : std::to_string(count) + " (0-" + std::to_string(count - 1) + ")";
}

} // namespace

std::vector<int> parseDeviceList(const std::string& text, int count) {
    const std::string option = "--devices " + text + ": ";
    const std::string expected = "expected all or a comma list of device indices (0,1,...)";
    std::vector<int> devices;
    if (text == "all") {
        for (int d = 0; d < count; ++d) devices.push_back(d);
    } else {
        std::stringstream items(text);
        std::string item;
        while (std::getline(items, item, ',')) {
            int device = -1;
            const auto [end, error] = std::from_chars(item.data(), item.data() + item.size(), device);
            if (item.empty() || error != std::errc() || end != item.data() + item.size() || device < 0)
                throw InputError(option + expected + ", not '" + item + "'", FailureKind::Usage);
            devices.push_back(device);
        }
        if (devices.empty() || text.back() == ',') throw InputError(option + expected, FailureKind::Usage);
    }
    if (count <= 0) throw InputError(option + "this machine has no CUDA device", FailureKind::Device);
    for (int device : devices)
        if (device >= count)
            throw InputError(option + "no CUDA device " + std::to_string(device) + ": this machine has " + devicesHere(count),
                             FailureKind::Device);
    return devices;
}

} // namespace urbis
