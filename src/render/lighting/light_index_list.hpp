// A light index list with no cap: per bin (cluster or tile) an (offset, count)
// range into one global array of light indices, each range in light order.
// The assignment costs what the lights touch, not lights times bins
// (shaders/common/light_scatter.glsl): each light visits the bins its sphere
// may reach, counts them and reserves its entries with one atomic add; a scan
// turns the bins' counts into ranges, the lights write themselves in, and a
// sort puts each range in light order. The frame never waits for the total:
// it is copied into a gfx::ReadbackRing and read one or more frames later,
// when its fence has passed, and the array is sized for the frames after from
// the entries per light that arrived, times this frame's lights (so a jump in
// light count is met at once), with headroom. Lights whose entries do not fit
// this frame go to an overflow list that every pixel they reach shades
// (common/list_shading.glsl): no light is dropped, only time, and only theirs.
// A list's first frame has no total to go by: it reads its total back in the
// frame (a counted GPU wait, never in a steady frame) and runs again once
// grown, so that a first frame of a million lights does not send nearly all of
// them to the overflow list. Where the driver ends shader loops early
// (llvmpipe) and there are more lights than that limit, the overflow list
// could outgrow the loop: there every frame sizes its list that way.
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
#include "gfx/shader_library.hpp"
#include "gfx/shader_program.hpp"
#include "render/frame_graph.hpp"

namespace atrium::lighting {

inline constexpr GLuint kLightRangesBinding = 2, kLightIndicesBinding = 3, kLightTotalBinding = 5, kBinCountsBinding = 7,
                        kBigLightsBinding = 12, kOverflowLightsBinding = 13, kLightFitsBinding = 14, kLongBinsBinding = 15;

// Entries per light the array is first sized for, before any total has arrived.
inline constexpr std::uint32_t kFirstEntriesPerLight = 4;

// How a technique's light lists map pixels to bins, published in the frame
// graph (FrameGraph::publish) by the technique that built them this frame, for
// the passes that read the lists (the light-lists view) and for tools.
struct LightBins {
  enum class Binning { Tiles, Clusters };
  Binning binning = Binning::Tiles;
  render::ResourceId lists;        // LightIndexList::import_into
  glm::uvec2 tiles{0};             // Tiles: tiles per row and column
  std::uint32_t tile_size = 0;     // Tiles: pixels per tile side
  const class LightIndexList* list = nullptr;  // binds the lists and their overflow (bind())
  GLuint grid_uniforms = 0;        // Clusters: the grid's uniform block (kClusterUniformBinding)
};

// A technique's assignment shader (including common/light_scatter.glsl: one
// program for most lights' steps, one for large lights') and the list's own scan and sorts
// (shaders/common/light_list_*.comp).
struct LightScatterPrograms {
  gfx::ShaderProgram& scatter;
  gfx::ShaderProgram& scatter_large;  // the same with LARGE_LIGHTS
  gfx::ShaderProgram& scan;
  gfx::ShaderProgram& sort_short;
  gfx::ShaderProgram& sort_long;
};

class LightIndexList {
 public:
  explicit LightIndexList(std::uint32_t bins);

  // The programs for a technique's assignment shader `source` with `defines`.
  [[nodiscard]] static LightScatterPrograms programs(gfx::ShaderLibrary& shaders, const std::string& source,
                                                     std::vector<gfx::ShaderDefine> defines = {});

  // Assigns `light_count` lights with `programs`; `bind_inputs` binds what the
  // technique's steps read (bin bounds, textures). Totals of earlier frames
  // that have arrived size the array first. Throws gfx::ResourceLimitError
  // when a total cannot fit.
  void assign(std::uint32_t light_count, const LightScatterPrograms& programs, const std::function<void()>& bind_inputs);
  // Takes in the totals of earlier frames whose fences have passed, without
  // waiting (assign() does this first; a one-shot command calls it after
  // waiting for the GPU). Throws gfx::ResourceLimitError.
  void poll();
  // Binds the ranges, indices, total and overflow list for shading.
  void bind() const;
  // The lists as one buffer resource of the frame graph (their ranges buffer
  // stands for them all; the size counts them all); `view`: LightBins where
  // the technique publishes how pixels map to the bins (LightBins).
  [[nodiscard]] render::ResourceId import_into(render::FrameGraph& graph, const std::string& name,
                                               render::ViewKind view = render::ViewKind::None) const;

  // Entries this frame's array holds; lights whose entries did not fit overflowed.
  [[nodiscard]] std::uint32_t capacity() const { return capacity_; }
  // The newest total that has arrived (a frame or more old, or this frame's where it was read back).
  [[nodiscard]] std::uint32_t last_total() const { return last_total_; }
  // Frames whose lists did not fit, counted as their totals arrive.
  [[nodiscard]] std::uint32_t overflow_frames() const { return overflow_frames_; }
  // The lists read back, per bin (for tests; they are in light order).
  [[nodiscard]] std::vector<std::vector<std::uint32_t>> read() const;

  // The candidate bins past which a light's steps get a work group of 64
  // invocations instead of one (shaders/common/light_scatter.glsl). On a GPU,
  // 512 where the lights alone make enough invocations, down to 32 for a few
  // hundred lights, whose bins a few dozen invocations would otherwise walk
  // in turn while the rest of the GPU waits (1,024 lights are 16 work groups).
  // On a software renderer always 512: its work groups' barriers cost more
  // than the spread saves there (measured, docs/benchmarks.md).
  [[nodiscard]] static std::uint32_t big_light_candidates(std::uint32_t light_count, bool software_renderer);

 private:
  // The demand, a flag the pass sets when it wrapped past 2^32, the longest
  // list, this frame's capacity and the overflowed lights
  // (shaders/common/light_lists.glsl's LightTotal).
  struct Total {
    std::uint32_t entries = 0;
    std::uint32_t wrapped = 0;
    std::uint32_t longest = 0;
    std::uint32_t capacity = 0;
    std::uint32_t overflow_lights = 0;
  };
  void resize(std::uint32_t capacity);
  void reserve_lights(std::uint32_t light_count);
  // Throws gfx::ResourceLimitError when `total` cannot be held.
  void check(const Total& total) const;
  // `drawn`: the frame drew with these lists (not run again once grown).
  void take(const Total& total, std::uint32_t light_count, bool drawn);
  void grow_for(std::uint64_t entries);
  void run(std::uint32_t light_count, const LightScatterPrograms& programs, const std::function<void()>& bind_inputs);

  std::uint32_t bins_;
  std::uint64_t max_entries_;  // what GL_MAX_SHADER_STORAGE_BLOCK_SIZE allows
  std::uint32_t loop_limit_;   // gfx::shader_loop_limit(): the longest loop a pixel may run
  bool software_;              // gfx::is_software_renderer(), asked once
  gfx::Buffer ranges_, indices_, total_, bin_counts_, long_bins_, overflow_, fits_, big_lights_;
  std::uint32_t light_capacity_ = 0;  // lights overflow_, fits_ and big_lights_ hold
  gfx::ReadbackRing totals_;  // each frame's Total on its way back, tagged with its light count
  std::uint32_t capacity_ = 0, last_total_ = 0, overflow_frames_ = 0;
  std::uint32_t wanted_ = 0;      // the largest total arrived since the array last grew
  double entries_per_light_ = kFirstEntriesPerLight;  // of the newest total that arrived
  bool arrived_ = false;          // a total has arrived: the list no longer sizes itself in the frame
};

}  // namespace atrium::lighting
