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
