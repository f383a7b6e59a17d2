#include "gfx/gpu_waits.hpp"

#include "gfx/gl_features.hpp"

namespace atrium::gfx {
namespace {

// GL calls are made on the context's thread; each thread counts its own.
thread_local std::uint64_t waits = 0;

}  // namespace

std::uint64_t gpu_waits() { return waits; }

void count_gpu_wait() { ++waits; }

void read_buffer(GLuint buffer, GLintptr offset, GLsizeiptr bytes, void* data) {
  ++waits;
  // Shaders' storage writes are incoherent: GL promises a read-back sees them
  // only after this barrier, so every read goes through it here.
  if (gl_features().memory_barriers) glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
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
