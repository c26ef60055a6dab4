// How much host memory a command may take (--max-memory), checked before the work that needs it
// (base/memory_requirement.h).
#pragma once

#include "base/memory_requirement.h"

#include <cstddef>
#include <string>

namespace urbis {

/// The bytes a command may take: `maxMemory` parsed (see parseMemorySize), or for an empty text
/// kDefaultMemoryShare of the memory available now; 0 where that is unknown (no limit).
size_t memoryLimit(const std::string& maxMemory);

} // namespace urbis
