// The cluster grid of the clustered techniques: the view frustum cut into
// screen tiles and depth slices (ZSlicing: by default a first slice from the
// near plane, then logarithmic slices to the far plane), each cluster's view-space bounds
// (rebuilt only when the projection changes), and the light assignment
// (shaders/clustered/assign.comp: each light visits the clusters it may
// reach) that fills one global light index list (LightIndexList: no cap per
// cluster).
// GLSL twin: shaders/common/clusters.glsl.
#pragma once

#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "render/binding_slots.hpp"
#include "gfx/gl_object.hpp"
#include "gfx/shader_library.hpp"
#include "gfx/shader_program.hpp"
#include "render/light_buffer.hpp"
#include "render/lighting/light_index_list.hpp"
#include "components/technique_options.hpp"

namespace atrium::lighting {

using render::kClusterUniformBinding, render::kPerClusterBinding;

// std140 twin of ClusterBlock in shaders/common/clusters.glsl.
struct ClusterUniforms {
  glm::uvec4 grid;      // xyz clusters per axis, w total
  glm::vec4 slicing;    // x first slice's far depth, y scale, z bias, w 1 = uniform (else log)
};
static_assert(sizeof(ClusterUniforms) == 32, "must match ClusterBlock in shaders/common/clusters.glsl");

struct ClusterBox {
  glm::vec4 lo;  // view space
  glm::vec4 hi;
};
static_assert(sizeof(ClusterBox) == 32, "must match ClusterBounds in shaders/clustered/assign.comp");

class ClusterGrid {
 public:
  explicit ClusterGrid(glm::uvec3 dims, ZSlicing slicing = ZSlicing::Log);

  // The assignment programs: with `bounds` Pixels, clusters are tested by the
  // box of their pixels (pixel_bounds_buffer(), filled by
  // shaders/clustered/mark_active.comp); else by the grid's boxes, and with
  // `active_only` clusters flagged inactive get no lights; `choice`: scatter, gather or per frame.
  [[nodiscard]] static LightAssignmentPrograms assign_programs(gfx::ShaderLibrary& shaders, ClusterBounds bounds, bool active_only,
                                                               LightAssignment choice = LightAssignment::Automatic);

  // Recomputes the slicing and the clusters' bounds if the projection changed.
  void update(const glm::mat4& projection, float near_plane, float far_plane);
  // Assigns the first `light_count` lights of the bound light buffer; `per_cluster`
  // is the buffer of per-cluster flags or pixel boxes the programs read, or 0.
  // Throws gfx::ResourceLimitError when the lists cannot fit.
  void assign(const LightAssignmentPrograms& programs, std::uint32_t light_count, GLuint per_cluster = 0);
  // Binds the uniform block and the range and index buffers for shading.
  void bind() const;
  // The grid's uniform block (common/clusters.glsl), for passes that bind it themselves.
  [[nodiscard]] GLuint uniform_buffer() const { return uniform_buffer_.id(); }

  [[nodiscard]] glm::uvec3 dims() const { return dims_; }
  [[nodiscard]] ZSlicing slicing() const { return slicing_; }
  [[nodiscard]] std::uint32_t cluster_count() const { return dims_.x * dims_.y * dims_.z; }
  [[nodiscard]] std::uint32_t slice_of(float view_depth) const;
  [[nodiscard]] const std::vector<ClusterBox>& boxes() const { return boxes_; }
  [[nodiscard]] const glm::mat4& projection() const { return projection_; }
  [[nodiscard]] float near_plane() const { return near_; }
  [[nodiscard]] const LightIndexList& list() const { return list_; }
  [[nodiscard]] LightIndexList& list() { return list_; }
  [[nodiscard]] std::uint32_t rebuilds() const { return rebuilds_; }
  [[nodiscard]] GLuint active_buffer() const { return active_.id(); }
  // Two uvec4 per cluster (least, then greatest view-space xyz as ordered integers).
  [[nodiscard]] GLuint pixel_bounds_buffer() const { return pixel_bounds_.id(); }
  // Empties every cluster's pixel box before mark_active.comp fills them.
  void clear_pixel_bounds() const;

  // The assignment done on the CPU with the same boxes and test, and the GPU's
  // lists read back: both as light indices per cluster, in light order (for tests).
  [[nodiscard]] std::vector<std::vector<std::uint32_t>> assign_on_cpu(std::span<const render::GpuLight> lights, const glm::mat4& view) const;
  [[nodiscard]] std::vector<std::vector<std::uint32_t>> read_lists() const { return list_.read(); }

 private:
  void upload_uniforms();

  glm::uvec3 dims_;
  ZSlicing slicing_;
  ClusterUniforms uniforms_{};
  std::vector<ClusterBox> boxes_;
  glm::mat4 projection_{0.0f};
  float near_ = 0.0f, far_ = 0.0f;
  gfx::Buffer uniform_buffer_, bounds_, active_, pixel_bounds_;
  LightIndexList list_;
  std::uint32_t rebuilds_ = 0;
};

}  // namespace atrium::lighting
