// The host's time of a step, as --stats and the commands' closing lines report it.
#pragma once

#include <chrono>

namespace urbis {

using SteadyClock = std::chrono::steady_clock;

/// Seconds from `start` to now.
inline double secondsSince(SteadyClock::time_point start) {
    return std::chrono::duration<double>(SteadyClock::now() - start).count();
}

} // namespace urbis
