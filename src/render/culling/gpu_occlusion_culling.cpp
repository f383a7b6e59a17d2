#include "render/binding_slots.hpp"
#include "render/culling/gpu_occlusion_culling.hpp"

#include <cstring>
#include <span>

#include "gfx/gl_features.hpp"
#include "render/culling/occlusion_culling.hpp"

namespace atrium::render {
namespace {

// The bindings of culling/depth_pyramid.comp, occlusion_cull.comp and compact_commands.comp.
constexpr GLuint kPyramidBinding = kDepthTilesBinding;
constexpr GLuint kTemplateBinding = kCommandTemplateBinding, kOutBinding = kCullOutBinding, kShownBinding = kCullShownBinding,
                 kRecordsBinding = kCullRecordsBinding, kCountersBinding = kCullCountersBinding;
constexpr int kMaxLevels = 16;  // occlusion_cull.comp's u_levels: 12 cover the largest render size (16384 pixels)
constexpr GLuint kCullGroup = 64;

enum Phase : unsigned { kFirst = 0, kReveal = 1, kRemember = 2 };

}  // namespace

std::vector<glm::ivec4> depth_pyramid_levels(glm::ivec2 viewport) {
  std::vector<glm::ivec4> levels;
  glm::ivec2 size = (viewport + DepthPyramid::kTileSize - 1) / DepthPyramid::kTileSize;
  if (size.x <= 0 || size.y <= 0) return levels;
  int offset = 0;
  while (true) {
    levels.emplace_back(size, offset, 0);
    offset += size.x * size.y;
    if (size.x <= 1 && size.y <= 1) break;
    size = (size + 1) / 2;
  }
  return levels;
}

GpuOcclusionCulling::GpuOcclusionCulling(gfx::ShaderLibrary& shaders)
    : shaders_(shaders), packs_(gfx::gl_features().indirect_count), counters_(gfx::create_buffer()), readback_(2 * sizeof(std::uint32_t)) {
  glNamedBufferStorage(counters_.id(), 2 * sizeof(std::uint32_t), nullptr, GL_DYNAMIC_STORAGE_BIT);
}

void GpuOcclusionCulling::begin(const DrawList& list, GLuint commands) {
  commands_ = commands;
  command_count_ = static_cast<std::uint32_t>(list.commands.size());
  opaque_count_ = static_cast<std::uint32_t>(list.cull_records.size());
  blended_triangles_ = 0;
  for (std::size_t c = opaque_count_; c < list.commands.size(); ++c) blended_triangles_ += list.commands[c].count / 3;
  const std::size_t command_bytes = std::max<std::size_t>(command_count_, 1) * sizeof(DrawCommand);
  first_.reserve(command_bytes);
  revealed_.reserve(command_bytes);
  shown_.reserve(command_bytes);
  records_.upload(list.cull_records.data(), list.cull_records.size() * sizeof(CullRecord));
  if (packs_) {
    // Every batch, by its count slot: opaque, then blended (draw_list.cpp).
    std::vector<glm::uvec2> batches;
    for (const auto* group : {&list.opaque, &list.blended}) {
      for (const DrawBatch& batch : *group) batches.emplace_back(batch.first_command, batch.command_count);
    }
    batch_count_ = static_cast<std::uint32_t>(batches.size());
    batches_.upload(batches.data(), batches.size() * sizeof(glm::uvec2));
    for (gfx::StreamBuffer& packed : packed_) packed.reserve(command_bytes);
    draw_counts_.reserve(std::max<std::size_t>(3 * batch_count_, 1) * sizeof(std::uint32_t));
  }
  // A scene whose entities changed renumbers its units: every one counts as
  // shown, so the first frame draws all that is in view in its first phase.
  if (list.cull_units != units_ || !last_shown_) {
    units_ = list.cull_units;
    last_shown_ = gfx::create_buffer();
    glNamedBufferStorage(last_shown_.id(), static_cast<GLsizeiptr>(std::max<std::uint32_t>(units_, 1) * sizeof(std::uint32_t)), nullptr, 0);
    const std::uint32_t one = 1;
    glClearNamedBufferData(last_shown_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &one);
  }
  const std::uint32_t zero = 0;
  glClearNamedBufferData(counters_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  cull(kFirst);
  pack(Phase::First);
}

void GpuOcclusionCulling::reveal(GLuint depth, glm::ivec2 size) {
  const gfx::KeepProgram keep;
  build_pyramid(depth, size);
  cull(kReveal);
  pack(Phase::Revealed);
  pack(Phase::Shown);
  readback_.copy(counters_.id(), 0, 2 * sizeof(std::uint32_t), blended_triangles_);
}

void GpuOcclusionCulling::remember(GLuint depth, glm::ivec2 size) {
  const gfx::KeepProgram keep;
  build_pyramid(depth, size);
  cull(kRemember);
}

const gfx::StreamBuffer& GpuOcclusionCulling::commands_of(Phase phase) const {
  switch (phase) {
    case Phase::First: return first_;
    case Phase::Revealed: return revealed_;
    case Phase::Shown: return shown_;
  }
  return first_;
}

void GpuOcclusionCulling::pack(Phase phase) {
  if (!packs_ || batch_count_ == 0) return;
  const auto p = static_cast<std::uint32_t>(phase);
  gfx::ShaderProgram& program = shaders_.get({"culling/compact_commands.comp"});
  program.use();
  program.set("u_count_offset", p * batch_count_);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kOutBinding, commands_of(phase).buffer.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kShownBinding, packed_[p].buffer.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kRecordsBinding, batches_.buffer.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kCountersBinding, draw_counts_.buffer.id());
  glDispatchCompute(batch_count_, 1, 1);
  glMemoryBarrier(GL_COMMAND_BARRIER_BIT);
}

GLintptr GpuOcclusionCulling::bind(Phase phase) const {
  if (!packs_) {
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, commands_of(phase).buffer.id());
    return -1;
  }
  const auto p = static_cast<std::uint32_t>(phase);
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, packed_[p].buffer.id());
  glBindBuffer(GL_PARAMETER_BUFFER_ARB, draw_counts_.buffer.id());
  return static_cast<GLintptr>(p * batch_count_ * sizeof(std::uint32_t));
}

void GpuOcclusionCulling::build_pyramid(GLuint depth, glm::ivec2 size) {
  levels_ = depth_pyramid_levels(size);
  if (levels_.empty() || static_cast<int>(levels_.size()) > kMaxLevels) return;
  const glm::ivec4 top = levels_.back();
  pyramid_.reserve(static_cast<std::size_t>(top.z + top.x * top.y) * sizeof(float));
  write_depth_tiles(shaders_, depth, glm::ivec2(levels_[0]), pyramid_.buffer.id());
  gfx::ShaderProgram& reduce = shaders_.get({"culling/depth_pyramid.comp"});
  reduce.use();
  for (std::size_t l = 1; l < levels_.size(); ++l) {
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    reduce.set("u_source", levels_[l - 1]);
    reduce.set("u_target", levels_[l]);
    glDispatchCompute(static_cast<GLuint>(levels_[l].x + 7) / 8, static_cast<GLuint>(levels_[l].y + 7) / 8, 1);
  }
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void GpuOcclusionCulling::cull(unsigned phase) {
  if (command_count_ == 0) return;
  gfx::ShaderProgram& program = shaders_.get({"culling/occlusion_cull.comp"});
  program.use();
  program.set("u_phase", phase);
  program.set("u_command_count", command_count_);
  program.set("u_opaque_count", opaque_count_);
  // Before the first phase no pyramid is read; an empty one hides nothing.
  const bool pyramid = phase != kFirst && !levels_.empty() && static_cast<int>(levels_.size()) <= kMaxLevels;
  program.set("u_level_count", pyramid ? static_cast<int>(levels_.size()) : 0);
  if (pyramid) program.set("u_levels", std::span<const glm::ivec4>(levels_));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kPyramidBinding, pyramid_.buffer ? pyramid_.buffer.id() : records_.buffer.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kTemplateBinding, commands_);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kOutBinding, phase == kFirst ? first_.buffer.id() : revealed_.buffer.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kShownBinding, shown_.buffer.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kRecordsBinding, records_.buffer.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kLastShownBinding, last_shown_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kCountersBinding, counters_.id());
  glDispatchCompute((command_count_ + kCullGroup - 1) / kCullGroup, 1, 1);
  // What the next phase or draw reads: the commands, and the shown bits.
  glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
}

std::optional<GpuCullingCounts> GpuOcclusionCulling::take_counts() {
  readback_.poll([&](const void* data, std::size_t bytes, std::uint64_t blended_triangles) {
    if (bytes < 2 * sizeof(std::uint32_t)) return;
    std::uint32_t counts[2];
    std::memcpy(counts, data, sizeof counts);
    counts_ = GpuCullingCounts{counts[0] + static_cast<std::size_t>(blended_triangles), counts[1]};
  });
  return counts_;
}

}  // namespace atrium::render
