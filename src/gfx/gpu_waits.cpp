#include "gfx/gpu_waits.hpp"

namespace atrium::gfx {
namespace {

// GL calls are made on the context's thread; each thread counts its own.
thread_local std::uint64_t waits = 0;

}  // namespace

std::uint64_t gpu_waits() { return waits; }

void count_gpu_wait() { ++waits; }

void read_buffer(GLuint buffer, GLintptr offset, GLsizeiptr bytes, void* data) {
  ++waits;
  glGetNamedBufferSubData(buffer, offset, bytes, data);
}

void read_texture(GLuint texture, GLint level, GLenum format, GLenum type, GLsizei bytes, void* data) {
  ++waits;
  glGetTextureImage(texture, level, format, type, bytes, data);
}

void finish() {
  ++waits;
  glFinish();
}

}  // namespace atrium::gfx
