// Checking CUDA runtime calls: a failed call becomes one InputError line naming the call.
// CUDA-only header (included by .cu files alone).
#pragma once

#include "base/input_error.h"

#include <cuda_runtime.h>

#include <string>

namespace urbis {

/// Throws InputError "CUDA error in CALL: ERROR STRING" unless `status` is cudaSuccess.
inline void cudaCheck(cudaError_t status, const char* call) {
    if (status != cudaSuccess)
        throw InputError(std::string("CUDA error in ") + call + ": " + cudaGetErrorString(status),
                         status == cudaErrorMemoryAllocation ? FailureKind::OutOfMemory : FailureKind::Device);
}

} // namespace urbis

/// Checks one CUDA runtime call; the macro only adds the call's text to the message.
#define URBIS_CUDA_CHECK(call) ::urbis::cudaCheck((call), #call)
