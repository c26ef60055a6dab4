// RAII page-locked host memory: copies between it and the device run asynchronously on their stream,
// where copies to pageable memory are staged by the driver and hold the host thread.
// CUDA-only header (included by .cu files alone).
#pragma once

#include "gpu/cuda_check.h"

#include <cstddef>
#include <cstdint>

namespace urbis {

/// Page-locked host bytes, grown on demand (contents not kept), freed on destruction.
class PinnedBuffer {
public:
    PinnedBuffer() = default;
    ~PinnedBuffer() { release(); }
    PinnedBuffer(const PinnedBuffer&) = delete;
    PinnedBuffer& operator=(const PinnedBuffer&) = delete;

    /// Makes room for at least `bytes`.
    void reserve(size_t bytes) {
        if (bytes <= bytes_) return;
        release();
        URBIS_CUDA_CHECK(cudaMallocHost(reinterpret_cast<void**>(&data_), bytes));
        bytes_ = bytes;
    }
    uint8_t* data() { return data_; }

private:
    void release() noexcept {
        if (data_) cudaFreeHost(data_);   // errors here are sticky ones already reported by the failing call
        data_ = nullptr;
        bytes_ = 0;
    }

    uint8_t* data_ = nullptr;
    size_t bytes_ = 0;
};

} // namespace urbis
