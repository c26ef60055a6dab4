#include "accel/wide_bvh_traverse.h"

namespace urbis {

WideIsa hostWideIsa() {
#if URBIS_HAVE_SSE
    return __builtin_cpu_supports("avx2") ? WideIsa::Avx2 : WideIsa::Sse;
#else
    return WideIsa::Scalar;
#endif
}

} // namespace urbis
