// What a step needs of the host memory a command may take (--max-memory), checked before the step.
#pragma once

#include <cstddef>
#include <string>

namespace urbis {

/// Share of the memory available at start that a command takes by default.
inline constexpr double kDefaultMemoryShare = 0.8;

/// Throws an out-of-memory InputError if `bytes`, what `what` needs, exceed `limit` (0: no
/// limit); the message gives both figures.
void requireMemory(size_t bytes, size_t limit, const std::string& what);

} // namespace urbis
