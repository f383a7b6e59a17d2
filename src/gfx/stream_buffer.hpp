// A buffer a pass refills every frame: it grows (doubling) to hold the largest
// upload so far and is never shrunk, so a steady frame allocates nothing.
#pragma once

#include <cstddef>

#include "gfx/gl_object.hpp"

namespace atrium::gfx {

struct StreamBuffer {
  Buffer buffer;
  std::size_t capacity = 0;  // bytes
  // Makes or grows the buffer to hold `bytes` (for what the GPU writes); its
  // contents are undefined after it grew.
  void reserve(std::size_t bytes);
  // Copies `bytes` from `data` to the start of the buffer (made or grown first).
  void upload(const void* data, std::size_t bytes);
};

}  // namespace atrium::gfx
