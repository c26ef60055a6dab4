#include "base/host_memory.h"

#include <sys/resource.h>

#include <fstream>
#include <string>

namespace urbis {

namespace {

/// The value of `field` ("VmHWM:") in /proc/self/status, in bytes (the file gives kB); 0 if absent.
size_t procStatusBytes(const std::string& field) {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.compare(0, field.size(), field) == 0) return size_t(std::stoull(line.substr(field.size()))) * 1024;
    return 0;
}

} // namespace

size_t peakHostBytes() {
    if (size_t bytes = procStatusBytes("VmHWM:")) return bytes;
    rusage usage{};
    return getrusage(RUSAGE_SELF, &usage) == 0 ? size_t(usage.ru_maxrss) * 1024 : 0;
}

size_t residentHostBytes() { return procStatusBytes("VmRSS:"); }

} // namespace urbis
