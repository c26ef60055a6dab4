#include "base/memory_requirement.h"

#include "base/input_error.h"

#include <cstdio>

namespace urbis {

void requireMemory(size_t bytes, size_t limit, const std::string& what) {
    if (limit == 0 || bytes <= limit) return;
    constexpr double kGiB = 1024.0 * 1024.0 * 1024.0;
    char message[320];
    std::snprintf(message, sizeof message,
                  "%s needs %zu bytes (%.2f GiB) of memory, more than the %zu bytes (%.2f GiB) allowed "
                  "(--max-memory; default %.0f %% of the memory available)",
                  what.c_str(), bytes, double(bytes) / kGiB, limit, double(limit) / kGiB, 100.0 * kDefaultMemoryShare);
    throw InputError(message, FailureKind::OutOfMemory);
}

} // namespace urbis
