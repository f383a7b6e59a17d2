#include "systems/lighting/light_index_list.hpp"

#include <algorithm>

namespace atrium::lighting {

LightIndexList::LightIndexList(std::uint32_t bins)
    : bins_(bins), ranges_(gfx::create_buffer()), total_(gfx::create_buffer()) {
  glNamedBufferStorage(ranges_.id(), static_cast<GLsizeiptr>(std::max<std::uint32_t>(bins, 1) * 2 * sizeof(std::uint32_t)), nullptr, 0);
  glNamedBufferStorage(total_.id(), sizeof(std::uint32_t), nullptr, GL_DYNAMIC_STORAGE_BIT);
  resize(4096);
}

void LightIndexList::resize(std::uint32_t capacity) {
  capacity_ = capacity;
  indices_ = gfx::create_buffer();
  glNamedBufferStorage(indices_.id(), static_cast<GLsizeiptr>(std::max<std::uint32_t>(capacity, 1) * sizeof(std::uint32_t)), nullptr, 0);
}

void LightIndexList::assign(const std::function<void()>& dispatch, const std::function<void(std::uint32_t)>& on_resize) {
  overflow_capacity_ = 0;
  for (int attempt = 0; attempt < 2; ++attempt) {
    const std::uint32_t zero = 0;
    glNamedBufferSubData(total_.id(), 0, sizeof zero, &zero);
    bind();
    dispatch();
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(total_.id(), 0, sizeof last_total_, &last_total_);
    if (last_total_ <= capacity_) return;
    // Too small for this frame: grow with room to spare and assign again.
    ++overflow_frames_;
    overflow_capacity_ = capacity_;
    resize(last_total_ + last_total_ / 4 + 64);
    on_resize(capacity_);
  }
}

void LightIndexList::bind() const {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kLightRangesBinding, ranges_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kLightIndicesBinding, indices_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kLightTotalBinding, total_.id());
}

std::vector<std::vector<std::uint32_t>> LightIndexList::read() const {
  std::vector<std::uint32_t> ranges(static_cast<std::size_t>(bins_) * 2), indices(capacity_);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glGetNamedBufferSubData(ranges_.id(), 0, static_cast<GLsizeiptr>(ranges.size() * sizeof(std::uint32_t)), ranges.data());
  glGetNamedBufferSubData(indices_.id(), 0, static_cast<GLsizeiptr>(indices.size() * sizeof(std::uint32_t)), indices.data());
  std::vector<std::vector<std::uint32_t>> lists(bins_);
  for (std::uint32_t b = 0; b < bins_; ++b) {
    const std::uint32_t offset = ranges[b * 2], count = ranges[b * 2 + 1];
    for (std::uint32_t i = 0; i < count && offset + i < capacity_; ++i) lists[b].push_back(indices[offset + i]);
    std::sort(lists[b].begin(), lists[b].end());
  }
  return lists;
}

}  // namespace atrium::lighting
