#include "gpu/gpu_gl_buffer.h"

#include "gpu/cuda_check.h"

#include <cuda_gl_interop.h>

#include <string>

namespace urbis {

struct CudaGlBuffer::Resource {
    cudaGraphicsResource_t handle = nullptr;
};

CudaGlBuffer::CudaGlBuffer(unsigned int buffer) : resource_(new Resource) {
    const cudaError_t status = cudaGraphicsGLRegisterBuffer(&resource_->handle, buffer, cudaGraphicsRegisterFlagsWriteDiscard);
    if (status != cudaSuccess) {
        delete resource_;
        cudaGetLastError();   // not sticky: the film goes on rendering
        throw InputError(std::string("CUDA-OpenGL interop: ") + cudaGetErrorString(status), FailureKind::Device);
    }
}

CudaGlBuffer::~CudaGlBuffer() {
    if (mapped_) cudaGraphicsUnmapResources(1, &resource_->handle);
    cudaGraphicsUnregisterResource(resource_->handle);   // errors here are sticky ones already reported
    delete resource_;
}

uint8_t* CudaGlBuffer::map() {
    URBIS_CUDA_CHECK(cudaGraphicsMapResources(1, &resource_->handle));
    mapped_ = true;
    void* data = nullptr;
    size_t bytes = 0;
    URBIS_CUDA_CHECK(cudaGraphicsResourceGetMappedPointer(&data, &bytes, resource_->handle));
    return static_cast<uint8_t*>(data);
}

void CudaGlBuffer::unmap() {
    mapped_ = false;
    URBIS_CUDA_CHECK(cudaGraphicsUnmapResources(1, &resource_->handle));
}

} // namespace urbis
