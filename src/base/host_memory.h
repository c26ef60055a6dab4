// The process's own host memory, as the kernel counts it, for --stats.
#pragma once

#include <cstddef>

namespace urbis {

/// The most resident memory the process has held so far, in bytes: VmHWM of /proc/self/status,
/// else getrusage's ru_maxrss; 0 where neither is known.
size_t peakHostBytes();

/// The resident memory now, in bytes: VmRSS of /proc/self/status; 0 where it cannot be read.
size_t residentHostBytes();

} // namespace urbis
