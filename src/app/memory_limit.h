// How much host memory a command may take (--max-memory), checked before the work that needs it.
#pragma once

#include <cstddef>
#include <string>

namespace urbis {

/// Share of the memory available at start that a command takes by default.
inline constexpr double kDefaultMemoryShare = 0.8;

/// The bytes a command may take: `maxMemory` parsed (see parseMemorySize), or for an empty text
/// kDefaultMemoryShare of the memory available now; 0 where that is unknown (no limit).
size_t memoryLimit(const std::string& maxMemory);

/// Throws an out-of-memory InputError if `bytes`, what `what` needs, exceed `limit` (0: no
/// limit); the message gives both figures.
void requireMemory(size_t bytes, size_t limit, const std::string& what);

} // namespace urbis
