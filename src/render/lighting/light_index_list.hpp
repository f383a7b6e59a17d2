// A light index list with no cap: per bin (cluster or tile) an (offset, count)
// range into one global array of light indices, each range in light order.
// Two assignments fill it, chosen per frame (LightAssignment, --light-assignment):
// the scatter (shaders/common/light_scatter.glsl) costs what the lights touch,
// not lights times bins: each light visits the bins its sphere may reach,
// counts them and reserves its entries with one atomic add; a scan turns the
// bins' counts into ranges, the lights write themselves in, and a sort puts
// each range in light order. Its atomics per hit are what dense lights (each
// reaching a large share of the bins) make expensive; there the gather
// (shaders/common/light_gather.glsl), each bin testing every light, costs
// bins times lights and needs neither atomics nor the sort. The frame never waits for the total:
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

#include "render/binding_slots.hpp"
#include "gfx/gl_object.hpp"
#include "gfx/readback_ring.hpp"
#include "gfx/shader_library.hpp"
#include "gfx/shader_program.hpp"
#include "components/technique_options.hpp"
#include "render/frame_graph.hpp"

namespace atrium::lighting {

using render::kBigLightsBinding, render::kBinCountsBinding, render::kScanBlocksBinding, render::kLightFitsBinding, render::kLightIndicesBinding,
    render::kLightRangesBinding, render::kLightTotalBinding, render::kLongBinsBinding, render::kOverflowLightsBinding;

// Entries per light the array is first sized for, before any total has arrived.
inline constexpr std::uint32_t kFirstEntriesPerLight = 4;

// The density (hits over bin-light tests) from which Automatic gathers
// (LightIndexList::assignment_for), as measured (docs/benchmarks.md). On
// llvmpipe the gather won down to 0.0038 (clustered, 16,384 lights) and lost
// at 0.0022 (50,000). On an H200 at 1080p, tiles: the gather won at 0.009
// (4,096 lights) and lost at 0.0028 (16,384), the GPU's atomics being cheap;
// clusters: it won down to 0.0006 (65,536) and tied at 0.0004 (131,072), a
// light's scatter visiting every cluster of the slices it spans, most of
// them empty, while the gather's blocks of empty clusters leave at once.
// Past 65,536 lights a GPU always scatters: each gather invocation walks every
// light in turn, and at 131,072 the scatter's invocation per light won or tied
// on every grid measured (16x9x32 clusters: 1.16 against 5.40 ms).
inline constexpr double kGatherDensitySoftware = 0.003;
inline constexpr double kGatherDensityGpuTiles = 0.005;
inline constexpr double kGatherDensityGpuClusters = 0.0005;
inline constexpr std::uint32_t kGatherMostLightsGpu = 65536;

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
  glm::uvec3 clusters{0};          // Clusters: clusters per axis
};

// "60x34x32 clusters" or "120x68 tiles of 16 px": how `bins` cut the frame.
[[nodiscard]] std::string describe(const LightBins& bins);

// A technique's assignment shader (including common/light_scatter.glsl: one
// program for most lights' steps, one for large lights'; with GATHER
// common/light_gather.glsl), the list's own scan and sorts
// (shaders/common/light_list_*.comp), and which assignment to run.
struct LightAssignmentPrograms {
  gfx::ShaderProgram& scatter;
  gfx::ShaderProgram& scatter_large;  // the same with LARGE_LIGHTS
  gfx::ShaderProgram& gather;         // the same with GATHER
  gfx::ShaderProgram& scan;
  gfx::ShaderProgram& sort_short;
  gfx::ShaderProgram& sort_long;
  LightAssignment choice = LightAssignment::Automatic;
};

class LightIndexList {
 public:
  // `shape`: bins per row, per column and per slice (tiles: one slice); the
  // gather walks them in blocks of 8x8 (shaders/common/light_gather.glsl).
  explicit LightIndexList(glm::uvec3 shape);

  // The programs for a technique's assignment shader `source` with `defines`,
  // running the assignment `choice` (Automatic: per frame, assignment_for()).
  [[nodiscard]] static LightAssignmentPrograms programs(gfx::ShaderLibrary& shaders, const std::string& source,
                                                        LightAssignment choice, std::vector<gfx::ShaderDefine> defines = {});

  // Assigns `light_count` lights with `programs`; `bind_inputs` binds what the
  // technique's steps read (bin bounds, textures). Totals of earlier frames
  // that have arrived size the array first. Throws gfx::ResourceLimitError
  // when a total cannot fit.
  void assign(std::uint32_t light_count, const LightAssignmentPrograms& programs, const std::function<void()>& bind_inputs);
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
  // The assignment the latest frame ran (Scatter or Gather).
  [[nodiscard]] LightAssignment last_assignment() const { return last_assignment_; }
  // The density of the newest total that arrived (assignment_for()): entries
  // over bins holding a light times lights; 0 before one arrived.
  [[nodiscard]] double last_density() const { return density_; }
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

  // Which assignment Automatic runs for `light_count` lights, from an earlier
  // frame's `entries` over `filled_bins` bins holding a light (none arrived:
  // both 0, the scatter): the gather where the density, entries over
  // filled_bins times lights (the share of the gather's light tests that are
  // hits), reaches kGatherDensitySoftware on a software renderer, else
  // kGatherDensityGpuClusters for bins in depth slices (`sliced`) or
  // kGatherDensityGpuTiles (and on a GPU at most kGatherMostLightsGpu
  // lights), so that the gather's tests cost less than the scatter's walk and
  // atomics. `loop_limit`: a driver's cap on a shader's
  // loop iterations (0: none), which the gather's walk over every light must
  // stay under.
  [[nodiscard]] static LightAssignment assignment_for(std::uint32_t light_count, std::uint64_t entries, std::uint32_t filled_bins,
                                                      std::uint32_t loop_limit, bool software_renderer, bool sliced);

 private:
  // The demand, a flag the pass sets when it wrapped past 2^32, the longest
  // list, this frame's capacity, the overflowed lights and the bins holding a
  // light (shaders/common/light_lists.glsl's LightTotal).
  struct Total {
    std::uint32_t entries = 0;
    std::uint32_t wrapped = 0;
    std::uint32_t longest = 0;
    std::uint32_t capacity = 0;
    std::uint32_t overflow_lights = 0;
    std::uint32_t filled_bins = 0;
  };
  void resize(std::uint32_t capacity);
  void reserve_lights(std::uint32_t light_count);
  // Throws gfx::ResourceLimitError when `total` cannot be held.
  void check(const Total& total) const;
  // `drawn`: the frame drew with these lists (not run again once grown).
  void take(const Total& total, std::uint32_t light_count, bool drawn);
  void grow_for(std::uint64_t entries);
  void run(std::uint32_t light_count, const LightAssignmentPrograms& programs, const std::function<void()>& bind_inputs);
  void scatter(std::uint32_t light_count, const LightAssignmentPrograms& programs);
  void gather(std::uint32_t light_count, const LightAssignmentPrograms& programs);
  // The bins' counts into ranges and cursors (shaders/common/light_list_scan.comp's three steps).
  void scan(const LightAssignmentPrograms& programs) const;

  glm::uvec3 shape_;
  std::uint32_t bins_;
  std::uint64_t max_entries_;  // what GL_MAX_SHADER_STORAGE_BLOCK_SIZE allows
  std::uint32_t loop_limit_;   // gfx::shader_loop_limit(): the longest loop a pixel may run
  bool software_;              // gfx::is_software_renderer(), asked once
  gfx::Buffer ranges_, indices_, total_, bin_counts_, long_bins_, overflow_, fits_, big_lights_;
  gfx::Buffer scan_blocks_;  // per block of the scan's bins: its sum, then its offset
  // The total's start (with the capacity) and an empty list's header, which
  // each frame copies over total_, long_bins_ and big_lights_ (made in resize).
  gfx::Buffer resets_;
  std::uint32_t light_capacity_ = 0;  // lights overflow_, fits_ and big_lights_ hold
  gfx::ReadbackRing totals_;  // each frame's Total on its way back, tagged with its light count
  std::uint32_t capacity_ = 0, last_total_ = 0, overflow_frames_ = 0;
  std::uint32_t wanted_ = 0;      // the largest total arrived since the array last grew
  double entries_per_light_ = kFirstEntriesPerLight;  // of the newest total that arrived
  bool arrived_ = false;          // a total has arrived: the list no longer sizes itself in the frame
  std::uint32_t filled_bins_ = 0; // of the newest total that arrived
  double density_ = 0.0;          // of the newest total that arrived
  LightAssignment last_assignment_ = LightAssignment::Scatter;
};

}  // namespace atrium::lighting
