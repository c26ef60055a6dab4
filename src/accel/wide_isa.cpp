#include "accel/wide_isa.h"

#include "urbis.h"

#include <cstdlib>
#include <cstring>

namespace urbis {

WideIsa hostWideIsa() {
#if URBIS_HAVE_SSE
    const WideIsa best = __builtin_cpu_supports("avx2") ? WideIsa::Avx2 : WideIsa::Sse;
    const char* asked = std::getenv("URBIS_WIDE_ISA");
    if (asked && std::strcmp(asked, "sse") == 0) return WideIsa::Sse;
    return best;
#else
    return WideIsa::Scalar;
#endif
}

} // namespace urbis
