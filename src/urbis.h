// The one portability header: the only place that knows about nvcc.
#pragma once

#if defined(__CUDACC__)
#define URBIS_HD __host__ __device__
#define URBIS_INLINE __forceinline__
#else
#define URBIS_HD
#define URBIS_INLINE inline
#endif

// Out of line in device code: one copy of a small function called from many places of the path
// tracing kernel, instead of one per call, keeps the kernel within the GPU's instruction cache
// (docs/gpu_notes.md). Inlined as usual on the CPU.
#if defined(__CUDA_ARCH__)
#define URBIS_DEVICE_NOINLINE __noinline__
#else
#define URBIS_DEVICE_NOINLINE
#endif

#if defined(__CUDA_ARCH__)
#define URBIS_GPU_CODE 1
#else
#define URBIS_GPU_CODE 0
#endif
