#include "render/lighting/light_index_list.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <string>

#include "base/format.hpp"
#include "gfx/gpu_waits.hpp"
#include "gfx/limits.hpp"
#include "gfx/pass_timer.hpp"

namespace atrium::lighting {
namespace {
constexpr GLuint kScatterGroup = 64, kSortGroupBins = 64, kMaxGroups = 65535;
// u_step in shaders/common/light_assignment.glsl.
constexpr std::uint32_t kStepCount = 0, kStepCountLarge = 1, kStepWrite = 2, kStepWriteLarge = 3, kStepOverflow = 4;
// Bins of a gather work group (shaders/common/light_gather.glsl); it walks its lights 1,024 at a time.
constexpr GLuint kGatherGroup = 64, kGatherBatch = 1024;
// Bins a work group of the scan takes (kScanBlock in shaders/common/light_list_scan.comp), and its steps (u_step).
constexpr GLuint kScanBlock = 4096;
constexpr std::uint32_t kScanReduce = 0, kScanBlocks = 1, kScanWrite = 2;
// LongBins in shaders/common/light_list_sort.glsl and BigLights in
// light_scatter.glsl: the dispatch's size, then the count, then the list.
constexpr std::size_t kListHeader = 4;
constexpr std::uint32_t kEmptyList[kListHeader] = {0, 1, 1, 0};
// Where the resets buffer keeps an empty list's header, after the total's start.
constexpr GLintptr kResetListOffset = 32;

// `groups` work groups in rows of at most kMaxGroups (a dispatch's limit on an
// axis); the shaders number a group y * groups-per-row + x.
void dispatch_in_rows(GLuint groups) { glDispatchCompute(std::min(groups, kMaxGroups), (groups + kMaxGroups - 1) / kMaxGroups, 1); }
}  // namespace

LightIndexList::LightIndexList(glm::uvec3 shape)
    : shape_(glm::max(shape, glm::uvec3(1))),
      bins_(shape_.x * shape_.y * shape_.z),
      max_entries_(std::min<std::uint64_t>(gfx::storage_block_limit() / sizeof(std::uint32_t), 0xffffffffu)),
      loop_limit_(gfx::shader_loop_limit()),
      software_(gfx::is_software_renderer()),
      ranges_(gfx::create_buffer()),
      total_(gfx::create_buffer()),
      bin_counts_(gfx::create_buffer()),
      long_bins_(gfx::create_buffer()),
      scan_blocks_(gfx::create_buffer()),
      totals_(sizeof(Total)) {
  static_assert(sizeof(Total) == 24, "must match LightTotal in shaders/common/light_lists.glsl");
  glNamedBufferStorage(ranges_.id(), static_cast<GLsizeiptr>(std::size_t{bins_} * 2 * sizeof(std::uint32_t)), nullptr, 0);
  glNamedBufferStorage(bin_counts_.id(), static_cast<GLsizeiptr>(std::size_t{bins_} * sizeof(std::uint32_t)), nullptr, 0);
  // Until a frame runs, the lists are empty and nothing overflowed.
  const Total none;
  glNamedBufferStorage(total_.id(), sizeof(Total), &none, 0);
  glNamedBufferStorage(long_bins_.id(), static_cast<GLsizeiptr>((kListHeader + std::size_t{bins_}) * sizeof(std::uint32_t)), nullptr, 0);
  glNamedBufferStorage(scan_blocks_.id(), static_cast<GLsizeiptr>((bins_ + kScanBlock - 1) / kScanBlock * sizeof(std::uint32_t)), nullptr, 0);
  const std::uint32_t zero = 0;
  glClearNamedBufferData(ranges_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  resize(static_cast<std::uint32_t>(std::min<std::uint64_t>(4096, std::max<std::uint64_t>(max_entries_, 1))));
  reserve_lights(1);
}

std::string describe(const LightBins& bins) {
  if (bins.binning == LightBins::Binning::Clusters) {
    return std::to_string(bins.clusters.x) + "x" + std::to_string(bins.clusters.y) + "x" + std::to_string(bins.clusters.z) + " clusters";
  }
  return std::to_string(bins.tiles.x) + "x" + std::to_string(bins.tiles.y) + " tiles of " + std::to_string(bins.tile_size) + " px";
}

LightAssignmentPrograms LightIndexList::programs(gfx::ShaderLibrary& shaders, const std::string& source, LightAssignment choice,
                                                 std::vector<gfx::ShaderDefine> defines) {
  auto with = [&](const char* define) {
    std::vector<gfx::ShaderDefine> more = defines;
    more.push_back({define});
    return more;
  };
  return {shaders.get({source}, defines),
          shaders.get({source}, with("LARGE_LIGHTS")),
          shaders.get({source}, with("GATHER")),
          shaders.get({"common/light_list_scan.comp"}),
          shaders.get({"common/light_list_sort.comp"}, {{"SHORT"}}),
          shaders.get({"common/light_list_sort.comp"}),
          choice};
}

namespace {
// Whether the gather's walk (every light once, plus per batch of lights one
// pass over the group's 64 segments and the staging's 16) stays under a
// driver's cap on loop iterations (0: none).
bool gather_fits_loops(std::uint32_t light_count, std::uint32_t loop_limit) {
  const std::uint64_t iterations = std::uint64_t{light_count} + (std::uint64_t{light_count} / kGatherBatch + 1) * (kGatherGroup + 16);
  return loop_limit == 0 || iterations < loop_limit;
}

// Entries over bins holding a light times lights: the share of a gather's tests that are hits.
double density(std::uint64_t entries, std::uint32_t filled_bins, std::uint32_t light_count) {
  return light_count > 0 && filled_bins > 0 ? static_cast<double>(entries) / (static_cast<double>(filled_bins) * light_count) : 0.0;
}
}  // namespace

LightAssignment LightIndexList::assignment_for(std::uint32_t light_count, std::uint64_t entries, std::uint32_t filled_bins,
                                               std::uint32_t loop_limit, bool software_renderer, bool sliced) {
  if (light_count == 0 || filled_bins == 0 || !gather_fits_loops(light_count, loop_limit)) return LightAssignment::Scatter;
  if (!software_renderer && light_count > kGatherMostLightsGpu) return LightAssignment::Scatter;
  const double threshold = software_renderer ? kGatherDensitySoftware : sliced ? kGatherDensityGpuClusters : kGatherDensityGpuTiles;
  return density(entries, filled_bins, light_count) >= threshold ? LightAssignment::Gather : LightAssignment::Scatter;
}

void LightIndexList::resize(std::uint32_t capacity) {
  capacity_ = capacity;
  indices_ = gfx::create_buffer();
  glNamedBufferStorage(indices_.id(), static_cast<GLsizeiptr>(std::max<std::uint32_t>(capacity, 1) * sizeof(std::uint32_t)), nullptr, 0);
  // A frame's starting values, which hold the capacity: made with it, never written after.
  static_assert(sizeof(Total) <= kResetListOffset);
  Total start;
  start.capacity = capacity_;
  std::array<unsigned char, kResetListOffset + sizeof kEmptyList> resets{};
  std::memcpy(resets.data(), &start, sizeof start);
  std::memcpy(resets.data() + kResetListOffset, kEmptyList, sizeof kEmptyList);
  resets_ = gfx::create_buffer();
  glNamedBufferStorage(resets_.id(), static_cast<GLsizeiptr>(resets.size()), resets.data(), 0);
}

void LightIndexList::reserve_lights(std::uint32_t light_count) {
  if (light_count <= light_capacity_ && fits_) return;
  light_capacity_ = std::max(light_count, light_capacity_ + light_capacity_ / 2);
  const auto bytes = static_cast<GLsizeiptr>(std::size_t{light_capacity_} * sizeof(std::uint32_t));
  overflow_ = gfx::create_buffer();
  fits_ = gfx::create_buffer();
  big_lights_ = gfx::create_buffer();
  glNamedBufferStorage(overflow_.id(), bytes, nullptr, 0);
  glNamedBufferStorage(fits_.id(), bytes, nullptr, 0);
  glNamedBufferStorage(big_lights_.id(), bytes + static_cast<GLsizeiptr>(kListHeader * sizeof(std::uint32_t)), nullptr, 0);
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

void LightIndexList::take(const Total& total, std::uint32_t light_count, bool drawn) {
  check(total);
  last_total_ = total.entries;
  if (drawn && total.overflow_lights > 0) ++overflow_frames_;
  wanted_ = std::max(wanted_, total.entries);
  filled_bins_ = total.filled_bins;
  density_ = density(total.entries, total.filled_bins, light_count);
  arrived_ = true;
  if (light_count > 0) entries_per_light_ = static_cast<double>(total.entries) / light_count;
}

void LightIndexList::grow_for(std::uint64_t entries) {
  if (entries <= capacity_) return;
  // Room to spare: lights that move change the total a little every frame.
  resize(static_cast<std::uint32_t>(std::min<std::uint64_t>(entries + entries / 4 + 64, max_entries_)));
}

void LightIndexList::poll() {
  totals_.poll([&](const void* data, std::size_t, std::uint64_t light_count) {
    Total total;
    std::memcpy(&total, data, sizeof total);
    take(total, static_cast<std::uint32_t>(light_count), true);
  });
}

std::uint32_t LightIndexList::big_light_candidates(std::uint32_t light_count, bool software_renderer) {
  constexpr std::uint32_t kMost = 512;
  return software_renderer ? kMost : std::clamp<std::uint32_t>(light_count / 32, 32, kMost);
}

void LightIndexList::run(std::uint32_t light_count, const LightAssignmentPrograms& programs, const std::function<void()>& bind_inputs) {
  LightAssignment method = programs.choice;
  const std::uint64_t entries = static_cast<std::uint64_t>(std::ceil(entries_per_light_ * light_count));
  if (method == LightAssignment::Automatic) method = assignment_for(light_count, arrived_ ? entries : 0, arrived_ ? filled_bins_ : 0, loop_limit_, software_, shape_.z > 1);
  // Asked for by name, the gather still keeps under a driver's loop cap (the scatter's lists are the same).
  if (method == LightAssignment::Gather && !gather_fits_loops(light_count, loop_limit_)) method = LightAssignment::Scatter;
  last_assignment_ = method;
  // Copies and a clear on the GPU, never an upload: uploading into a buffer
  // that earlier commands may use made the CPU wait for them (on an H200 for
  // the whole G-buffer pass, 4-5 ms a frame, before each light assignment).
  glCopyNamedBufferSubData(resets_.id(), total_.id(), 0, 0, sizeof(Total));
  const std::uint32_t zero = 0;
  glClearNamedBufferData(bin_counts_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  glCopyNamedBufferSubData(resets_.id(), long_bins_.id(), kResetListOffset, 0, sizeof kEmptyList);
  glCopyNamedBufferSubData(resets_.id(), big_lights_.id(), kResetListOffset, 0, sizeof kEmptyList);
  bind();
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, render::kLongBinsBinding, long_bins_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, render::kBinCountsBinding, bin_counts_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, render::kLightFitsBinding, fits_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, render::kBigLightsBinding, big_lights_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, render::kScanBlocksBinding, scan_blocks_.id());
  bind_inputs();
  if (method == LightAssignment::Gather) gather(light_count, programs);
  else scatter(light_count, programs);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

void LightIndexList::gather(std::uint32_t light_count, const LightAssignmentPrograms& programs) {
  // Blocks of 8x8 bins (kGatherGroup), per slice.
  const GLuint groups = ((shape_.x + 7) / 8) * ((shape_.y + 7) / 8) * shape_.z;
  {
    const gfx::PassTimer::Step step("count");
    programs.gather.use();
    programs.gather.set("u_bin_shape", shape_);
    programs.gather.set("u_step", kStepCount);
    dispatch_in_rows(groups);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }
  scan(programs);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  const gfx::PassTimer::Step step("write");
  programs.gather.use();
  programs.gather.set("u_step", kStepWrite);
  dispatch_in_rows(groups);
  // Only a frame whose demand did not fit lists its lights as overflowed (each invocation checks).
  const GLuint light_groups = (light_count + kScatterGroup - 1) / kScatterGroup;
  if (light_groups > 0) {
    programs.gather.set("u_step", kStepOverflow);
    glDispatchCompute(light_groups, 1, 1);
  }
}

void LightIndexList::scan(const LightAssignmentPrograms& programs) const {
  const gfx::PassTimer::Step step("scan");
  const GLuint blocks = (bins_ + kScanBlock - 1) / kScanBlock;
  programs.scan.use();
  programs.scan.set("u_bins", bins_);
  programs.scan.set("u_step", kScanReduce);
  dispatch_in_rows(blocks);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  programs.scan.set("u_step", kScanBlocks);
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  programs.scan.set("u_step", kScanWrite);
  dispatch_in_rows(blocks);
}

void LightIndexList::scatter(std::uint32_t light_count, const LightAssignmentPrograms& programs) {
  const GLuint light_groups = (light_count + kScatterGroup - 1) / kScatterGroup;
  // The large lights, a work group each: as many as the count step listed (no read-back).
  auto large_lights = [&](std::uint32_t step) {
    programs.scatter_large.use();
    programs.scatter_large.set("u_step", step);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, big_lights_.id());
    glDispatchComputeIndirect(0);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
  };
  if (light_groups > 0) {
    const gfx::PassTimer::Step step("count");
    programs.scatter.use();
    programs.scatter.set("u_big_light", big_light_candidates(light_count, software_));
    programs.scatter.set("u_step", kStepCount);
    glDispatchCompute(light_groups, 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
    large_lights(kStepCountLarge);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }
  scan(programs);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
  if (light_groups > 0) {
    {
      const gfx::PassTimer::Step step("write");
      programs.scatter.use();
      programs.scatter.set("u_step", kStepWrite);
      glDispatchCompute(light_groups, 1, 1);
      large_lights(kStepWriteLarge);
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
    const gfx::PassTimer::Step step("sort");
    const GLuint sort_groups = (bins_ + kSortGroupBins - 1) / kSortGroupBins;
    programs.sort_short.use();
    programs.sort_short.set("u_bins", bins_);
    dispatch_in_rows(sort_groups);
    // The long lists, as many work groups as the scan found (no read-back).
    programs.sort_long.use();
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, long_bins_.id());
    glDispatchComputeIndirect(0);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
  }
}

void LightIndexList::assign(std::uint32_t light_count, const LightAssignmentPrograms& programs, const std::function<void()>& bind_inputs) {
  poll();
  // This frame's lights at the entries per light last seen: a jump in the
  // light count is met in the frame it happens, not one later.
  grow_for(std::max<std::uint64_t>(wanted_, static_cast<std::uint64_t>(std::ceil(entries_per_light_ * light_count))));
  wanted_ = 0;
  reserve_lights(light_count);
  run(light_count, programs, bind_inputs);
  if (!arrived_ || (loop_limit_ && light_count > loop_limit_)) {
    // Nothing to size the first frame by, or an overflow list that could hold
    // more lights than a pixel may loop over: size the array in this frame.
    Total total;
    gfx::read_buffer(total_.id(), 0, sizeof total, &total);
    take(total, light_count, total.overflow_lights == 0);
    if (total.overflow_lights == 0) return;
    grow_for(total.entries);
    run(light_count, programs, bind_inputs);
    return;
  }
  (void)totals_.copy(total_.id(), 0, sizeof(Total), light_count);
}

void LightIndexList::bind() const {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, render::kLightRangesBinding, ranges_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, render::kLightIndicesBinding, indices_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, render::kLightTotalBinding, total_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, render::kOverflowLightsBinding, overflow_.id());
}

render::ResourceId LightIndexList::import_into(render::FrameGraph& graph, const std::string& name, render::ViewKind view) const {
  const std::size_t bytes =
      (static_cast<std::size_t>(bins_) * 4 + capacity_ + 3 * std::size_t{light_capacity_} + 2 * kListHeader) * sizeof(std::uint32_t) + sizeof(Total) +
      kResetListOffset + sizeof kEmptyList;
  return graph.import_buffer(name, ranges_.id(), {bytes}, view);
}

std::vector<std::vector<std::uint32_t>> LightIndexList::read() const {
  std::vector<std::uint32_t> ranges(static_cast<std::size_t>(bins_) * 2), indices(capacity_);
  gfx::read_buffer(ranges_.id(), 0, static_cast<GLsizeiptr>(ranges.size() * sizeof(std::uint32_t)), ranges.data());
  gfx::read_buffer(indices_.id(), 0, static_cast<GLsizeiptr>(indices.size() * sizeof(std::uint32_t)), indices.data());
  std::vector<std::vector<std::uint32_t>> lists(bins_);
  for (std::uint32_t b = 0; b < bins_; ++b) {
    const std::uint32_t offset = ranges[b * 2], count = ranges[b * 2 + 1];
    for (std::uint32_t i = 0; i < count && offset + i < capacity_; ++i) lists[b].push_back(indices[offset + i]);
  }
  return lists;
}

}  // namespace atrium::lighting
