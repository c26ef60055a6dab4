// CUDA-OpenGL interop where the build has none (no CUDA, or no OpenGL headers): buffers never register.
#include "gpu/gpu_gl_buffer.h"

#include "base/input_error.h"

namespace urbis {

struct CudaGlBuffer::Resource {};

CudaGlBuffer::CudaGlBuffer(unsigned int) {
    throw InputError("CUDA-OpenGL interop: this build has none (built without CUDA or OpenGL headers)", FailureKind::Device);
}
CudaGlBuffer::~CudaGlBuffer() = default;
uint8_t* CudaGlBuffer::map() { return nullptr; }
void CudaGlBuffer::unmap() {}

} // namespace urbis
