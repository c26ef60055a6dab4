#include "scene/memory_budget.h"

#include <fstream>
#include <string>

namespace urbis {

size_t availableMemoryBytes() {
    std::ifstream meminfo("/proc/meminfo");
    std::string key;
    size_t kib = 0;
    while (meminfo >> key >> kib) {
        if (key == "MemAvailable:") return kib * 1024;
        meminfo.ignore(256, '\n');
    }
    return 0;
}

} // namespace urbis
