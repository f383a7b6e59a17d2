#include "gfx/stream_buffer.hpp"

#include <algorithm>
#include <cstring>

#include "gfx/gl_features.hpp"

namespace atrium::gfx {
namespace {
constexpr GLbitfield kMapping = GL_MAP_WRITE_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
}  // namespace

void StreamBuffer::reserve(std::size_t bytes) {
  if (bytes <= capacity && buffer) return;
  capacity = std::max({bytes, 2 * capacity, std::size_t{256}});
  buffer = create_buffer();
  glNamedBufferStorage(buffer.id(), static_cast<GLsizeiptr>(capacity), nullptr, GL_DYNAMIC_STORAGE_BIT);
}

void StreamBuffer::upload(const void* data, std::size_t bytes) {
  upload({std::span<const std::byte>(static_cast<const std::byte*>(data), bytes)});
}

void StreamBuffer::upload(std::initializer_list<std::span<const std::byte>> pieces) {
  std::size_t bytes = 0;
  for (const std::span<const std::byte> piece : pieces) bytes += piece.size();
  reserve(bytes);
  if (bytes == 0) return;
  if (gl_features().buffer_storage && !unmappable_ && (staging_.empty() || staging_bytes_ != capacity)) make_staging();
  if (staging_.empty()) {
    std::size_t offset = 0;
    for (const std::span<const std::byte> piece : pieces) {
      if (!piece.empty()) {
        glNamedBufferSubData(buffer.id(), static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(piece.size()), piece.data());
      }
      offset += piece.size();
    }
    return;
  }
  Staging& copy = staging_[next_];
  next_ = (next_ + 1) % staging_.size();
  copy.copied.wait();
  std::size_t offset = 0;
  for (const std::span<const std::byte> piece : pieces) {
    if (!piece.empty()) std::memcpy(static_cast<std::byte*>(copy.mapped) + offset, piece.data(), piece.size());
    offset += piece.size();
  }
  glCopyNamedBufferSubData(copy.buffer.id(), buffer.id(), 0, 0, static_cast<GLsizeiptr>(bytes));
  copy.copied.place();
}

void StreamBuffer::make_staging() {
  // Every copy at once and as large as the buffer, so that what a stream holds
  // follows from its largest upload alone. Copies the GPU may still read are
  // freed by GL once it has.
  staging_.clear();
  staging_bytes_ = capacity;
  next_ = 0;
  for (std::size_t i = 0; i < kStagingCopies; ++i) {
    Staging copy;
    copy.buffer = create_buffer();
    glNamedBufferStorage(copy.buffer.id(), static_cast<GLsizeiptr>(capacity), nullptr, kMapping);
    copy.mapped = glMapNamedBufferRange(copy.buffer.id(), 0, static_cast<GLsizeiptr>(capacity), kMapping);
    if (!copy.mapped) {
      staging_.clear();
      unmappable_ = true;
      return;
    }
    staging_.push_back(std::move(copy));
  }
}

}  // namespace atrium::gfx
