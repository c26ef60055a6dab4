// The instruction sets the 8-wide BVH's lanes are tested in, and the one this CPU runs (host).
#pragma once

#include <cstdint>

namespace urbis {

/// The instruction sets a wide node's eight lanes are tested in (WideLanesScalar, WideLanesSse,
/// WideLanesAvx2): all three compute the same values bit for bit (the same IEEE operations in the
/// same order), so they find the same hits. The GPU takes the scalar one.
enum class WideIsa : uint8_t { Scalar, Sse, Avx2 };

/// The fastest lane test this CPU runs: AVX2 where it has it, else SSE on x86, else scalar; the
/// environment variable URBIS_WIDE_ISA=sse asks for SSE on a CPU with AVX2 (to compare them: the
/// images are the same).
WideIsa hostWideIsa();

} // namespace urbis
