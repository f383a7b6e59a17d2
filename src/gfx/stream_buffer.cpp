#include "gfx/stream_buffer.hpp"

#include <algorithm>

namespace atrium::gfx {

void StreamBuffer::reserve(std::size_t bytes) {
  if (bytes <= capacity && buffer) return;
  capacity = std::max({bytes, 2 * capacity, std::size_t{256}});
  buffer = create_buffer();
  glNamedBufferStorage(buffer.id(), static_cast<GLsizeiptr>(capacity), nullptr, GL_DYNAMIC_STORAGE_BIT);
}

void StreamBuffer::upload(const void* data, std::size_t bytes) {
  reserve(bytes);
  if (bytes) glNamedBufferSubData(buffer.id(), 0, static_cast<GLsizeiptr>(bytes), data);
}

}  // namespace atrium::gfx
