// What a render call did, as both backends report it.
#pragma once

#include <cstdint>

namespace urbis {

struct RenderCounters {
    uint64_t rays = 0;     ///< rays the path tracer traced (the AOV pass not counted)
    double seconds = 0;    ///< wall time of the render (GPU: its kernels' time)
};

} // namespace urbis
