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

// A constant table that per-ray code indexes: in device memory on the GPU (nvcc's device pass), an
// ordinary constant elsewhere.
#if URBIS_GPU_CODE
#define URBIS_TABLE static __device__ constexpr
#else
#define URBIS_TABLE inline constexpr
#endif

// Keeps nvcc from unrolling the loop that follows, where code size matters more than the loop's
// overhead (the GPU's instruction cache: docs/gpu_notes.md).
#if URBIS_GPU_CODE
#define URBIS_NO_UNROLL _Pragma("unroll 1")
#else
#define URBIS_NO_UNROLL
#endif
