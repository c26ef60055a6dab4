// An OpenGL buffer object that CUDA writes (CUDA-OpenGL interop): the viewer's window shows the CUDA
// film's picture through it with no copy to the host (docs/viewer.md). Built from gpu_gl_buffer.cu
// where CUDA and OpenGL's headers are found, else from gpu_gl_buffer_none.cpp, whose buffers never
// register (the window then copies the picture through the host).
#pragma once

#include <cstddef>
#include <cstdint>

namespace urbis {

class CudaGlBuffer {
public:
    /// Registers the OpenGL buffer object `buffer` of the current context for CUDA to write whole
    /// (cudaGraphicsGLRegisterBuffer). Throws InputError where CUDA cannot: a build without interop,
    /// or a context on a device CUDA does not drive (a software renderer, another GPU).
    explicit CudaGlBuffer(unsigned int buffer);
    ~CudaGlBuffer();
    CudaGlBuffer(const CudaGlBuffer&) = delete;
    CudaGlBuffer& operator=(const CudaGlBuffer&) = delete;

    /// Maps the buffer for CUDA and returns its device address; OpenGL must not use it until unmap().
    uint8_t* map();
    void unmap();

    struct Resource;

private:
    Resource* resource_ = nullptr;
    bool mapped_ = false;
};

} // namespace urbis
