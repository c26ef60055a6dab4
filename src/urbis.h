// The one portability header: the only place that knows about nvcc.
#pragma once

#if defined(__CUDACC__)
#define URBIS_HD __host__ __device__
#define URBIS_INLINE __forceinline__
#else
#define URBIS_HD
#define URBIS_INLINE inline
#endif

#if defined(__CUDA_ARCH__)
#define URBIS_GPU_CODE 1
#else
#define URBIS_GPU_CODE 0
#endif

// SSE on x86 CPUs (the BVH's four-lane slab test); never in nvcc's device pass.
#if !URBIS_GPU_CODE && (defined(__SSE2__) || defined(_M_X64))
#define URBIS_HAVE_SSE 1
#else
#define URBIS_HAVE_SSE 0
#endif

// A constant table that per-ray code indexes: in device memory on the GPU (nvcc's device pass), an
// ordinary constant elsewhere.
#if URBIS_GPU_CODE
#define URBIS_TABLE static __device__ constexpr
#else
#define URBIS_TABLE inline constexpr
#endif

// Keeps nvcc from unrolling the loop that follows, where code size matters more than the loop's
// overhead: the GPU render kernel is bound by its instruction cache.
#if URBIS_GPU_CODE
#define URBIS_NO_UNROLL _Pragma("unroll 1")
#else
#define URBIS_NO_UNROLL
#endif

namespace urbis {

// Precision policy. The GPU build contracts multiply-adds and uses the hardware's approximate
// division, square root and transcendentals (--use_fast_math), so shading code is plain math. The
// few routines that decide *which* primitive a ray hits at what distance (the BVH slab test,
// BvhRay::safeInverse, the watertight triangle test, the wall slabs and grid walk, the ground) must
// give the same bits on both backends: they use these, each one IEEE operation rounded to nearest,
// never fused with another (CUDA's __f*_rn intrinsics; the plain operators on the host, where g++
// in ISO mode does not contract).

/// a * b, rounded once, never fused into a multiply-add.
URBIS_HD inline float exactMul(float a, float b) {
#if URBIS_GPU_CODE
    return __fmul_rn(a, b);
#else
    return a * b;
#endif
}
/// a + b, rounded once, never fused with a product.
URBIS_HD inline float exactAdd(float a, float b) {
#if URBIS_GPU_CODE
    return __fadd_rn(a, b);
#else
    return a + b;
#endif
}
/// a - b, rounded once, never fused with a product.
URBIS_HD inline float exactSub(float a, float b) {
#if URBIS_GPU_CODE
    return __fsub_rn(a, b);
#else
    return a - b;
#endif
}
/// a / b, correctly rounded (IEEE), whatever the build's division flags.
URBIS_HD inline float exactDiv(float a, float b) {
#if URBIS_GPU_CODE
    return __fdiv_rn(a, b);
#else
    return a / b;
#endif
}
/// sqrt(a), correctly rounded (IEEE), whatever the build's square-root flags.
URBIS_HD inline float exactSqrt(float a) {
#if URBIS_GPU_CODE
    return __fsqrt_rn(a);
#else
    return __builtin_sqrtf(a);
#endif
}
/// a * b + c with two roundings (the product's, then the sum's), as the CPU computes it.
URBIS_HD inline float exactMulAdd(float a, float b, float c) { return exactAdd(exactMul(a, b), c); }

} // namespace urbis
