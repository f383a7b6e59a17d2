// Calls that can make the CPU wait for the GPU: reading back what the GPU
// wrote (buffers, textures), glFinish, a query result that is not yet there.
// On a GPU each one drains the queue and leaves it idle while the CPU prepares
// what follows, so a steady frame should make none. Every such call in the
// engine goes through these wrappers, which count it; the renderer reports the
// count per frame (overlay, bench CSV column gpu_waits). The software
// renderer's pass timing (glFinish around each pass, PassTimer's CpuFinish) is
// not counted: it exists only where the driver's timer queries are wrong.
#pragma once

#include <cstdint>

#include "gfx/gl.hpp"

namespace atrium::gfx {

// Calls that could wait made on this thread since it started (never reset).
[[nodiscard]] std::uint64_t gpu_waits();
// Counts one call that could wait, for code that must make it itself.
void count_gpu_wait();

// glGetNamedBufferSubData after the barrier that lets it see what shaders
// wrote to the buffer, counted.
void read_buffer(GLuint buffer, GLintptr offset, GLsizeiptr bytes, void* data);
// glGetTextureImage, counted.
void read_texture(GLuint texture, GLint level, GLenum format, GLenum type, GLsizei bytes, void* data);
// glFinish, counted.
void finish();

}  // namespace atrium::gfx
