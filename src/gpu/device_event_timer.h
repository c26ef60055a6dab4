// Timing device work with a pair of CUDA events (CUDA-only: compiled by nvcc).
#pragma once

#include "gpu/cuda_check.h"

namespace urbis {

/// A pair of CUDA events around device work; elapsed time in milliseconds.
class EventTimer {
public:
    EventTimer() {
        URBIS_CUDA_CHECK(cudaEventCreate(&start_));
        URBIS_CUDA_CHECK(cudaEventCreate(&stop_));
    }
    ~EventTimer() {
        cudaEventDestroy(start_);
        cudaEventDestroy(stop_);
    }
    EventTimer(const EventTimer&) = delete;
    EventTimer& operator=(const EventTimer&) = delete;
    void start() { URBIS_CUDA_CHECK(cudaEventRecord(start_)); }
    float stopMs() {
        URBIS_CUDA_CHECK(cudaEventRecord(stop_));
        URBIS_CUDA_CHECK(cudaEventSynchronize(stop_));
        float ms = 0;
        URBIS_CUDA_CHECK(cudaEventElapsedTime(&ms, start_, stop_));
        return ms;
    }

private:
    cudaEvent_t start_ = nullptr, stop_ = nullptr;
};

} // namespace urbis
