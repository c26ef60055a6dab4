// RAII device memory for arrays of POD records (after tiny-cuda-nn's GPUMemory<T>).
// CUDA-only header (included by .cu files alone).
#pragma once

#include "gpu/cuda_check.h"

#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

namespace urbis {

/// An array of `T` in device memory, freed on destruction; moves, never copies.
template <typename T>
class DeviceBuffer {
    static_assert(std::is_trivially_copyable_v<T>, "device buffers hold POD records");

public:
    DeviceBuffer() = default;
    explicit DeviceBuffer(size_t count) { resize(count); }
    ~DeviceBuffer() { release(); }
    DeviceBuffer(DeviceBuffer&& other) noexcept { swap(other); }
    DeviceBuffer& operator=(DeviceBuffer&& other) noexcept {
        DeviceBuffer moved(std::move(other));
        swap(moved);
        return *this;
    }
    DeviceBuffer(const DeviceBuffer&) = delete;
    DeviceBuffer& operator=(const DeviceBuffer&) = delete;

    /// Makes room for `count` elements (contents undefined); keeps the allocation if the size is the same.
    void resize(size_t count) {
        if (count == count_) return;
        release();
        if (count > 0) URBIS_CUDA_CHECK(cudaMalloc(reinterpret_cast<void**>(&data_), count * sizeof(T)));
        count_ = count;
    }
    /// Copies `count` host elements to the device, resizing to exactly that many.
    void upload(const T* host, size_t count) {
        resize(count);
        if (count > 0) URBIS_CUDA_CHECK(cudaMemcpy(data_, host, count * sizeof(T), cudaMemcpyHostToDevice));
    }
    void upload(const std::vector<T>& host) { upload(host.data(), host.size()); }
    /// The whole array, copied back to the host.
    std::vector<T> download() const {
        std::vector<T> host(count_);
        if (count_ > 0) URBIS_CUDA_CHECK(cudaMemcpy(host.data(), data_, count_ * sizeof(T), cudaMemcpyDeviceToHost));
        return host;
    }

    T* data() { return data_; }
    const T* data() const { return data_; }
    size_t size() const { return count_; }
    size_t bytes() const { return count_ * sizeof(T); }

private:
    void release() noexcept {
        if (data_) cudaFree(data_);   // errors here are sticky ones already reported by the failing call
        data_ = nullptr;
        count_ = 0;
    }
    void swap(DeviceBuffer& other) noexcept {
        std::swap(data_, other.data_);
        std::swap(count_, other.count_);
    }

    T* data_ = nullptr;
    size_t count_ = 0;
};

} // namespace urbis
