// A light index list with no cap: per bin (cluster or tile) an (offset, count)
// range into one global array of light indices. An assignment pass counts each
// bin's lights, reserves its range with an atomic add on a total, and writes.
// The array is sized from the previous frame's total; when a frame's total does
// not fit, the array grows and the pass runs again (counted as an overflow).
// A total beyond what one storage buffer may hold (or beyond 2^32 entries, which
// the pass flags) raises gfx::ResourceLimitError naming the memory needed.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "gfx/gl_object.hpp"
#include "render/frame_graph.hpp"

namespace atrium::lighting {

inline constexpr GLuint kLightRangesBinding = 2, kLightIndicesBinding = 3, kLightTotalBinding = 5;

class LightIndexList {
 public:
  explicit LightIndexList(std::uint32_t bins);

  // Runs `dispatch` (which must read the capacity through `capacity()` or the
  // uniform set by `on_resize`) until the whole list fits. Throws
  // gfx::ResourceLimitError when it cannot fit.
  void assign(const std::function<void()>& dispatch, const std::function<void(std::uint32_t)>& on_resize);
  void bind() const;
  // The lists as one buffer resource of the frame graph (their ranges buffer
  // stands for all three; the size counts them all).
  [[nodiscard]] render::ResourceId import_into(render::FrameGraph& graph, const std::string& name) const;

  [[nodiscard]] std::uint32_t capacity() const { return capacity_; }
  [[nodiscard]] std::uint32_t last_total() const { return last_total_; }
  [[nodiscard]] std::uint32_t overflow_frames() const { return overflow_frames_; }
  // The capacity the latest assignment first ran with if it overflowed, else 0:
  // bins whose range ends beyond it would have lost lights without the growth.
  [[nodiscard]] std::uint32_t overflow_capacity() const { return overflow_capacity_; }
  // The lists read back, sorted, per bin (for tests).
  [[nodiscard]] std::vector<std::vector<std::uint32_t>> read() const;

 private:
  void resize(std::uint32_t capacity);

  std::uint32_t bins_;
  std::uint64_t max_entries_;  // what GL_MAX_SHADER_STORAGE_BLOCK_SIZE allows
  std::uint32_t loop_limit_;   // gfx::shader_loop_limit(): the longest list shading may loop over
  gfx::Buffer ranges_, indices_, total_;
  std::uint32_t capacity_ = 0, last_total_ = 0, overflow_frames_ = 0, overflow_capacity_ = 0;
};

}  // namespace atrium::lighting
