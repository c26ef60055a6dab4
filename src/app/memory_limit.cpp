#include "app/memory_limit.h"

#include "app/option_parsing.h"
#include "scene/memory_budget.h"

namespace urbis {

size_t memoryLimit(const std::string& maxMemory) {
    if (!maxMemory.empty()) return parseMemorySize("--max-memory", maxMemory);
    return size_t(kDefaultMemoryShare * double(availableMemoryBytes()));
}

} // namespace urbis
