#include "app/render_device.h"

#include "base/input_error.h"

#include <cstdio>
#include <fstream>

namespace urbis {

std::string cpuModelName() {
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string line;
    while (std::getline(cpuinfo, line))
        if (line.rfind("model name", 0) == 0) {
            size_t colon = line.find(':');
            if (colon != std::string::npos && colon + 2 <= line.size()) return line.substr(colon + 2);
        }
    return "cpu";
}

LinearImage renderOnDevice(const Scene& scene, const Camera& camera, const RenderSettings& settings,
                           const std::string& device, bool showProgress, bool verbose, RenderCounters& counters,
                           DeviceReport& report) {
    const bool sayDevice = verbose || device == "cuda";
    if (device != "cpu") {
        GpuInfo info = probeGpu();
        if (!info.available && device == "cuda") throw InputError("--device cuda: " + info.reason, FailureKind::Device);
        if (info.available) {
            try {
                size_t filmBytes = size_t(settings.width) * settings.height * sizeof(Vec3f);
                std::unique_ptr<GpuScene> gpu = GpuScene::upload(scene, filmBytes);
                if (sayDevice) std::fprintf(stderr, "urbis: rendering on %s (cuda)\n", info.name.c_str());
                LinearImage image = gpu->render(camera, settings, counters);
                report = DeviceReport{"cuda", info.name, gpu->memory()};
                return image;
            } catch (const InputError& e) {
                if (device == "cuda") throw;
                std::fprintf(stderr, "urbis: %s; falling back to the CPU\n", e.what());
            }
        } else if (sayDevice) {
            std::fprintf(stderr, "urbis: rendering on the CPU (%s)\n", info.reason.c_str());
        }
    }
    report = DeviceReport{"cpu", cpuModelName(), GpuMemory{}};
    return renderCpu(scene.view(), camera, settings, showProgress, counters);
}

} // namespace urbis
