// A light index list with no cap: per bin (cluster or tile) an (offset, count)
// range into one global array of light indices. An assignment pass counts each
// bin's lights, reserves its range with an atomic add on a total, and writes
// what fits. The frame never waits for the total: it is copied into a
// gfx::ReadbackRing and read one or more frames later, when its fence has
// passed, and the array grows (with headroom) for the frames after. A bin whose range
// ends past this frame's capacity overflowed: shading loops over every light
// for its pixels (common/list_shading.glsl), so no light is dropped, only time.
// Where the driver ends shader loops early (llvmpipe) and there are more lights
// than that limit, that fallback cannot hold them all: there the total is read
// back in the frame (a counted GPU wait) and the pass runs again once grown.
// A total beyond what one storage buffer may hold (or beyond 2^32 entries,
// which the pass flags) raises gfx::ResourceLimitError naming the memory
// needed, in the frame that learns it.
#pragma once

#include <functional>

#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "gfx/gl_object.hpp"
#include "gfx/readback_ring.hpp"
#include "render/frame_graph.hpp"

namespace atrium::lighting {

inline constexpr GLuint kLightRangesBinding = 2, kLightIndicesBinding = 3, kLightTotalBinding = 5;

// How a technique's light lists map pixels to bins, published in the frame
// graph (FrameGraph::publish) by the technique that built them this frame, for
// the passes that read the lists (the light-lists view) and for tools.
struct LightBins {
  enum class Binning { Tiles, Clusters };
  Binning binning = Binning::Tiles;
  render::ResourceId lists;        // LightIndexList::import_into: binds as the ranges (kLightRangesBinding)
  glm::uvec2 tiles{0};             // Tiles: tiles per row and column
  std::uint32_t tile_size = 0;     // Tiles: pixels per tile side
  const class LightIndexList* list = nullptr;  // its capacity() as the lists ran: bins ending past it overflowed
  GLuint grid_uniforms = 0;        // Clusters: the grid's uniform block (kClusterUniformBinding)
};

class LightIndexList {
 public:
  explicit LightIndexList(std::uint32_t bins);

  // Runs `dispatch` (which must read the capacity through `capacity()` or the
  // uniform set by `on_resize`) for `light_count` lights. Totals of earlier
  // frames that have arrived grow the list first (calling `on_resize`). Throws
  // gfx::ResourceLimitError when a total cannot fit.
  void assign(std::uint32_t light_count, const std::function<void()>& dispatch, const std::function<void(std::uint32_t)>& on_resize);
  // Takes in the totals of earlier frames whose fences have passed, without
  // waiting (assign() does this first; a one-shot command calls it after
  // waiting for the GPU). Throws gfx::ResourceLimitError.
  void poll();
  void bind() const;
  // The lists as one buffer resource of the frame graph (their ranges buffer
  // stands for all three; the size counts them all); `view`: LightBins where
  // the technique publishes how pixels map to the bins (LightBins).
  [[nodiscard]] render::ResourceId import_into(render::FrameGraph& graph, const std::string& name,
                                               render::ViewKind view = render::ViewKind::None) const;

  // Entries this frame's lists may hold; a bin whose range ends past it overflowed.
  [[nodiscard]] std::uint32_t capacity() const { return capacity_; }
  // The newest total that has arrived (a frame or more old, or this frame's where it was read back).
  [[nodiscard]] std::uint32_t last_total() const { return last_total_; }
  // Frames whose lists did not fit, counted as their totals arrive.
  [[nodiscard]] std::uint32_t overflow_frames() const { return overflow_frames_; }
  // The lists read back, sorted, per bin (for tests; a bin that overflowed
  // holds what fitted).
  [[nodiscard]] std::vector<std::vector<std::uint32_t>> read() const;

 private:
  // The running total, a flag the pass sets when the total wrapped past 2^32,
  // and the longest list (shaders/common/light_lists.glsl's LightTotal).
  struct Total {
    std::uint32_t entries = 0;
    std::uint32_t wrapped = 0;
    std::uint32_t longest = 0;
  };
  void resize(std::uint32_t capacity);
  // Throws gfx::ResourceLimitError when `total` cannot be held.
  void check(const Total& total) const;
  void grow_for(std::uint32_t entries, const std::function<void(std::uint32_t)>& on_resize);

  std::uint32_t bins_;
  std::uint64_t max_entries_;  // what GL_MAX_SHADER_STORAGE_BLOCK_SIZE allows
  std::uint32_t loop_limit_;   // gfx::shader_loop_limit(): the longest loop a pixel may run
  gfx::Buffer ranges_, indices_, total_;
  gfx::ReadbackRing totals_;  // each frame's Total on its way back, tagged with the capacity it ran with
  std::uint32_t capacity_ = 0, last_total_ = 0, overflow_frames_ = 0;
  std::uint32_t wanted_ = 0;  // the largest total arrived since the list last grew
};

}  // namespace atrium::lighting
