#include "gfx/readback_ring.hpp"

#include <algorithm>

#include "gfx/gl_features.hpp"

namespace atrium::gfx {

namespace {
constexpr GLbitfield kMapping = GL_MAP_READ_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
}  // namespace

ReadbackRing::ReadbackRing(std::size_t slot_bytes, std::size_t slots)
    : slot_bytes_(std::max<std::size_t>(slot_bytes, 4)), buffer_(create_buffer()), slots_(std::max<std::size_t>(slots, 1)) {
  const auto total = static_cast<GLsizeiptr>(slot_bytes_ * slots_.size());
  if (gl_features().full_tier()) copy_program_ = ShaderProgram::load({"common/readback_copy.comp"});
  if (gl_features().buffer_storage) {
    glNamedBufferStorage(buffer_.id(), total, nullptr, kMapping);
    mapped_ = static_cast<const unsigned char*>(glMapNamedBufferRange(buffer_.id(), 0, total, kMapping));
  } else {
    // No persistent mapping (OpenGL 4.1, ES 3.0): a slot is read with
    // glGetBufferSubData once its fence has passed, which does not wait either.
    glNamedBufferData(buffer_.id(), total, nullptr, GL_STREAM_READ);
    staging_.resize(slot_bytes_);
  }
}

ReadbackRing::~ReadbackRing() {
  if (mapped_) glUnmapNamedBuffer(buffer_.id());
}

bool ReadbackRing::copy(GLuint buffer, GLintptr offset, std::size_t bytes, std::uint64_t tag) {
  Slot& slot = slots_[next_];
  if (slot.fence.placed() || bytes > slot_bytes_ || (!mapped_ && staging_.empty())) return false;
  const std::size_t destination = next_ * slot_bytes_;
  if (copy_program_ && bytes % 4 == 0 && offset % 4 == 0 && destination % 4 == 0) {
    // The shader reads what shaders wrote, and the CPU reads what it writes.
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    const KeepProgram keep;
    copy_program_.use();
    copy_program_.set("u_source_word", static_cast<unsigned>(offset / 4));
    copy_program_.set("u_slot_word", static_cast<unsigned>(destination / 4));
    copy_program_.set("u_words", static_cast<unsigned>(bytes / 4));
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kReadbackSourceBinding, buffer);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kReadbackSlotBinding, buffer_.id());
    glDispatchCompute(static_cast<GLuint>((bytes / 4 + 63) / 64), 1, 1);
    glMemoryBarrier(GL_CLIENT_MAPPED_BUFFER_BARRIER_BIT);
  } else {
    // The copy reads what shaders wrote through storage or images.
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glCopyNamedBufferSubData(buffer, buffer_.id(), offset, static_cast<GLintptr>(destination), static_cast<GLsizeiptr>(bytes));
  }
  slot.fence.place();
  slot.bytes = bytes;
  slot.tag = tag;
  slot.order = copies_++;
  next_ = (next_ + 1) % slots_.size();
  return true;
}

void ReadbackRing::poll(const std::function<void(const void* data, std::size_t bytes, std::uint64_t tag)>& arrived) {
  std::vector<std::size_t> done;
  for (std::size_t i = 0; i < slots_.size(); ++i) {
    if (slots_[i].fence.passed()) done.push_back(i);
  }
  std::sort(done.begin(), done.end(), [&](std::size_t a, std::size_t b) { return slots_[a].order < slots_[b].order; });
  for (const std::size_t i : done) {
    slots_[i].fence.reset();
    if (mapped_) {
      arrived(mapped_ + i * slot_bytes_, slots_[i].bytes, slots_[i].tag);
    } else {
      glGetNamedBufferSubData(buffer_.id(), static_cast<GLintptr>(i * slot_bytes_), static_cast<GLsizeiptr>(slots_[i].bytes),
                              staging_.data());
      arrived(staging_.data(), slots_[i].bytes, slots_[i].tag);
    }
  }
}

}  // namespace atrium::gfx
