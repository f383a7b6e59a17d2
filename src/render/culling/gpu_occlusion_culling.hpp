// Occlusion culling with nothing read back (--culling gpu): the same two phases
// and the same box test as the CPU path (occlusion_culling.hpp), on the GPU.
// The frame's list holds everything in view, one indirect command per
// primitive or meshlet with its box (DrawSelection::EachInView); the depth
// pyramid is built from the depth buffer by culling/depth_tiles.comp and
// culling/depth_pyramid.comp, and culling/occlusion_cull.comp writes the
// commands each phase draws (instance count 0 for what it leaves out) and,
// from the same test, which units the next frame draws first: one pyramid a
// frame (two on a camera cut). Where GL 4.6 or
// ARB_indirect_parameters has glMultiDrawElementsIndirectCount,
// culling/compact_commands.comp then packs each batch's drawn commands to the
// front of its range, in order, and draws take their count from the GPU.
// Its counts come back through a ReadbackRing a frame or more late.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "gfx/gl_object.hpp"
#include "gfx/readback_ring.hpp"
#include "gfx/shader_library.hpp"
#include "gfx/stream_buffer.hpp"
#include "render/frame/draw_list.hpp"

namespace atrium::render {

struct GpuCullingCounts {
  std::size_t triangles_drawn = 0;   // by the passes after the first (opaque shown and blended)
  std::size_t triangles_hidden = 0;  // in view, hidden by the first phase's depth and drawn by no pass
};

// The levels of a depth pyramid over a `viewport`-sized depth buffer: per
// level, xy its size in texels (8x8-pixel tiles at level 0, each level half
// the one below, rounded up, down to 1x1) and z the offset of its first texel
// when all levels lie in one array, finest first.
[[nodiscard]] std::vector<glm::ivec4> depth_pyramid_levels(glm::ivec2 viewport);

class GpuOcclusionCulling {
 public:
  explicit GpuOcclusionCulling(gfx::ShaderLibrary& shaders);

  // Uploads the boxes of `list` (a DrawSelection::EachInView list whose
  // commands are in `commands`) and writes first_commands(): what the last
  // frame showed. The frame uniforms must be bound.
  void begin(const DrawList& list, GLuint commands);
  // After the first phase drew into `depth`: writes revealed_commands() (what
  // that depth does not hide and was not drawn) and shown_commands() (both),
  // remembers what it does not hide for the next frame's first phase and
  // queues the frame's counts.
  void reveal(GLuint depth, glm::ivec2 size);
  // On a camera cut, after the revealed commands drew into `depth`: chooses
  // what the next frame draws first from that depth instead.
  void remember(GLuint depth, glm::ivec2 size);

  // Which commands the next draws take (GL_DRAW_INDIRECT_BUFFER, and with
  // packing the parameter buffer): returns the CommandSource::count_base to
  // draw them with (-1: every command).
  enum class Phase { First, Revealed, Shown };
  [[nodiscard]] GLintptr bind(Phase phase) const;
  [[nodiscard]] bool packs() const { return packs_; }

  // The newest counts that have arrived; nullopt until one has. Never waits.
  [[nodiscard]] std::optional<GpuCullingCounts> take_counts();

 private:
  void build_pyramid(GLuint depth, glm::ivec2 size);
  void cull(unsigned phase);
  // Packs `phase`'s commands and writes its batches' counts.
  void pack(Phase phase);
  [[nodiscard]] const gfx::StreamBuffer& commands_of(Phase phase) const;

  gfx::ShaderLibrary& shaders_;
  gfx::StreamBuffer first_, revealed_, shown_, records_, pyramid_;
  bool packs_;  // glMultiDrawElementsIndirectCount is there
  gfx::StreamBuffer packed_[3], batches_, draw_counts_;  // per phase; per batch (first, count); 3 counts per batch
  std::uint32_t batch_count_ = 0;
  GLuint commands_ = 0;
  std::uint32_t command_count_ = 0, opaque_count_ = 0;
  std::size_t blended_triangles_ = 0;
  gfx::Buffer last_shown_;  // one uint per unit: 1 where the last frame's first depth did not hide it
  std::uint32_t units_ = 0;
  gfx::Buffer counters_;  // occlusion_cull.comp's u_counters
  std::vector<glm::ivec4> levels_;
  gfx::ReadbackRing readback_;
  std::optional<GpuCullingCounts> counts_;
};

}  // namespace atrium::render
