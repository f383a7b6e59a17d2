#include "render/lighting/light_index_list.hpp"

#include <algorithm>
#include <cstring>
#include <string>

#include "base/format.hpp"
#include "gfx/gpu_waits.hpp"
#include "gfx/limits.hpp"

namespace atrium::lighting {

LightIndexList::LightIndexList(std::uint32_t bins)
    : bins_(bins),
      max_entries_(std::min<std::uint64_t>(gfx::storage_block_limit() / sizeof(std::uint32_t), 0xffffffffu)),
      loop_limit_(gfx::shader_loop_limit()),
      ranges_(gfx::create_buffer()),
      total_(gfx::create_buffer()),
      totals_(sizeof(Total)) {
  static_assert(sizeof(Total) == 12, "must match LightTotal in shaders/common/light_lists.glsl");
  glNamedBufferStorage(ranges_.id(), static_cast<GLsizeiptr>(std::max<std::uint32_t>(bins, 1) * 2 * sizeof(std::uint32_t)), nullptr, 0);
  glNamedBufferStorage(total_.id(), sizeof(Total), nullptr, GL_DYNAMIC_STORAGE_BIT);
  resize(static_cast<std::uint32_t>(std::min<std::uint64_t>(4096, std::max<std::uint64_t>(max_entries_, 1))));
}

void LightIndexList::resize(std::uint32_t capacity) {
  capacity_ = capacity;
  indices_ = gfx::create_buffer();
  glNamedBufferStorage(indices_.id(), static_cast<GLsizeiptr>(std::max<std::uint32_t>(capacity, 1) * sizeof(std::uint32_t)), nullptr, 0);
}

void LightIndexList::check(const Total& total) const {
  if (total.wrapped || total.entries > max_entries_) {
    const std::string entries = total.wrapped ? "more than 4,294,967,295" : with_commas(total.entries);
    const std::string bytes = total.wrapped ? "over 16 GiB" : format_bytes(static_cast<double>(std::uint64_t{total.entries} * sizeof(std::uint32_t)));
    throw gfx::ResourceLimitError("the light lists need " + entries + " entries (" + bytes + "), more than one storage buffer may hold here (" +
                                  format_bytes(static_cast<double>(max_entries_ * sizeof(std::uint32_t))) +
                                  ", GL_MAX_SHADER_STORAGE_BLOCK_SIZE); use fewer lights (--lights), smaller ones (--light-radius), "
                                  "fewer clusters (--cluster-grid) or, for tiles, a smaller image (--size)");
  }
  if (loop_limit_ && total.longest > loop_limit_) {
    throw gfx::ResourceLimitError("one tile or cluster holds " + with_commas(total.longest) + " lights, and this driver ends a shader's loops after " +
                                  with_commas(loop_limit_) + " iterations (llvmpipe), so its pixels would leave lights out; use fewer "
                                  "lights (--lights), smaller ones (--light-radius) or more bins (--cluster-grid, or a larger --size for tiles)");
  }
}

void LightIndexList::grow_for(std::uint32_t entries, const std::function<void(std::uint32_t)>& on_resize) {
  if (entries <= capacity_) return;
  // Room to spare: lights that move change the total a little every frame.
  resize(static_cast<std::uint32_t>(std::min<std::uint64_t>(std::uint64_t{entries} + entries / 4 + 64, max_entries_)));
  on_resize(capacity_);
}

void LightIndexList::poll() {
  totals_.poll([&](const void* data, std::size_t, std::uint64_t capacity) {
    Total total;
    std::memcpy(&total, data, sizeof total);
    check(total);
    last_total_ = total.entries;
    if (total.entries > capacity) ++overflow_frames_;
    wanted_ = std::max(wanted_, total.entries);
  });
}

void LightIndexList::assign(std::uint32_t light_count, const std::function<void()>& dispatch,
                            const std::function<void(std::uint32_t)>& on_resize) {
  poll();
  grow_for(wanted_, on_resize);
  wanted_ = 0;
  auto run = [&] {
    const Total zero;
    glNamedBufferSubData(total_.id(), 0, sizeof zero, &zero);
    bind();
    dispatch();
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  };
  run();
  if (loop_limit_ && light_count > loop_limit_) {
    // An overflowed bin's pixels would loop over more lights than the driver
    // allows: size the list in this frame instead.
    Total total;
    gfx::read_buffer(total_.id(), 0, sizeof total, &total);
    check(total);
    last_total_ = total.entries;
    if (total.entries <= capacity_) return;
    ++overflow_frames_;
    grow_for(total.entries, on_resize);
    run();
    return;
  }
  (void)totals_.copy(total_.id(), 0, sizeof(Total), capacity_);
}

void LightIndexList::bind() const {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kLightRangesBinding, ranges_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kLightIndicesBinding, indices_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kLightTotalBinding, total_.id());
}

render::ResourceId LightIndexList::import_into(render::FrameGraph& graph, const std::string& name, render::ViewKind view) const {
  const std::size_t bytes = (static_cast<std::size_t>(bins_) * 2 + capacity_ + 1) * sizeof(std::uint32_t);
  return graph.import_buffer(name, ranges_.id(), {bytes}, view);
}

std::vector<std::vector<std::uint32_t>> LightIndexList::read() const {
  std::vector<std::uint32_t> ranges(static_cast<std::size_t>(bins_) * 2), indices(capacity_);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  gfx::read_buffer(ranges_.id(), 0, static_cast<GLsizeiptr>(ranges.size() * sizeof(std::uint32_t)), ranges.data());
  gfx::read_buffer(indices_.id(), 0, static_cast<GLsizeiptr>(indices.size() * sizeof(std::uint32_t)), indices.data());
  std::vector<std::vector<std::uint32_t>> lists(bins_);
  for (std::uint32_t b = 0; b < bins_; ++b) {
    const std::uint32_t offset = ranges[b * 2], count = ranges[b * 2 + 1];
    for (std::uint32_t i = 0; i < count && offset + i < capacity_; ++i) lists[b].push_back(indices[offset + i]);
    std::sort(lists[b].begin(), lists[b].end());
  }
  return lists;
}

}  // namespace atrium::lighting
