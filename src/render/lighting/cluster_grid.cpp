#include "render/lighting/cluster_grid.hpp"


#include <algorithm>
#include <cmath>
#include <string>

#include "gfx/depth.hpp"

namespace atrium::lighting {
namespace {
constexpr GLuint kBoundsBinding = render::kBinBoundsBinding;
}  // namespace

LightAssignmentPrograms ClusterGrid::assign_programs(gfx::ShaderLibrary& shaders, ClusterBounds bounds, bool active_only,
                                                     LightAssignment choice) {
  std::vector<gfx::ShaderDefine> defines;
  if (bounds == ClusterBounds::Pixels) defines.push_back({"PIXEL_BOUNDS"});
  else if (active_only) defines.push_back({"ACTIVE_ONLY"});
  return LightIndexList::programs(shaders, "clustered/assign.comp", choice, defines);
}

ClusterGrid::ClusterGrid(glm::uvec3 dims, ZSlicing slicing)
    : dims_(glm::max(dims, glm::uvec3(1, 1, 2))),
      slicing_(slicing),
      uniform_buffer_(gfx::create_buffer()),
      bounds_(gfx::create_buffer()),
      active_(gfx::create_buffer()),
      pixel_bounds_(gfx::create_buffer()),
      list_(dims_) {
  glNamedBufferStorage(uniform_buffer_.id(), sizeof(ClusterUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT);
  glNamedBufferStorage(bounds_.id(), static_cast<GLsizeiptr>(cluster_count() * sizeof(ClusterBox)), nullptr, GL_DYNAMIC_STORAGE_BIT);
  // Written only by the GPU (shaders and clears): no storage the CPU may update.
  glNamedBufferStorage(active_.id(), static_cast<GLsizeiptr>(cluster_count() * sizeof(std::uint32_t)), nullptr, 0);
  glNamedBufferStorage(pixel_bounds_.id(), static_cast<GLsizeiptr>(2 * std::size_t{cluster_count()} * sizeof(glm::uvec4)), nullptr, 0);
  upload_uniforms();
}

void ClusterGrid::clear_pixel_bounds() const {
  // Least starts at the greatest ordered value, greatest at the least: empty.
  const GLsizeiptr half = static_cast<GLsizeiptr>(std::size_t{cluster_count()} * sizeof(glm::uvec4));
  const glm::uvec4 high(0xffffffffu), low(0u);
  glClearNamedBufferSubData(pixel_bounds_.id(), GL_RGBA32UI, 0, half, GL_RGBA_INTEGER, GL_UNSIGNED_INT, &high);
  glClearNamedBufferSubData(pixel_bounds_.id(), GL_RGBA32UI, half, half, GL_RGBA_INTEGER, GL_UNSIGNED_INT, &low);
}

void ClusterGrid::upload_uniforms() {
  glNamedBufferSubData(uniform_buffer_.id(), 0, sizeof(ClusterUniforms), &uniforms_);
}

void ClusterGrid::update(const glm::mat4& projection, float near_plane, float far_plane) {
  if (projection == projection_ && near_plane == near_ && far_plane == far_) return;
  projection_ = projection;
  near_ = near_plane;
  far_ = far_plane;
  ++rebuilds_;
  // Every scheme maps a depth past the first slice to slice = f(depth) * scale + bias,
  // f the logarithm or (uniform) the identity; boundary b >= 1 lies at f^-1((b - bias) / scale).
  const auto slices = static_cast<float>(dims_.z);
  const bool linear = slicing_ == ZSlicing::Uniform;
  float first = 0.0f, scale = 0.0f, bias = 0.0f;
  switch (slicing_) {
    case ZSlicing::Log:
      // The first slice ends ten near-plane distances out (or earlier for a short frustum).
      first = std::min(near_plane * 10.0f, near_plane + (far_plane - near_plane) / slices);
      scale = (slices - 1.0f) / std::log(far_plane / first);
      bias = 1.0f - std::log(first) * scale;
      break;
    case ZSlicing::PlainLog:
      scale = slices / std::log(far_plane / near_plane);
      bias = -std::log(near_plane) * scale;
      first = std::exp((1.0f - bias) / scale);
      break;
    case ZSlicing::Uniform:
      scale = slices / (far_plane - near_plane);
      bias = -near_plane * scale;
      first = near_plane + (far_plane - near_plane) / slices;
      break;
  }
  uniforms_.grid = glm::uvec4(dims_, cluster_count());
  uniforms_.slicing = glm::vec4(first, scale, bias, linear ? 1.0f : 0.0f);
  upload_uniforms();

  // Each cluster's box: the tile's four corner rays cut at the slice's depths.
  const glm::mat4 inverse = glm::inverse(projection);
  auto slice_depth = [&](std::uint32_t boundary) {
    if (boundary == 0) return near_plane;
    if (boundary == 1) return first;
    if (boundary == dims_.z) return far_plane;
    const float x = (static_cast<float>(boundary) - bias) / scale;
    return linear ? x : std::exp(x);
  };
  boxes_.resize(cluster_count());
  for (std::uint32_t z = 0; z < dims_.z; ++z) {
    const float d0 = slice_depth(z), d1 = slice_depth(z + 1);
    for (std::uint32_t y = 0; y < dims_.y; ++y) {
      for (std::uint32_t x = 0; x < dims_.x; ++x) {
        glm::vec3 lo(1e30f), hi(-1e30f);
        for (int corner = 0; corner < 4; ++corner) {
          const float ndc_x = -1.0f + 2.0f * static_cast<float>(x + (corner & 1)) / static_cast<float>(dims_.x);
          const float ndc_y = -1.0f + 2.0f * static_cast<float>(y + ((corner >> 1) & 1)) / static_cast<float>(dims_.y);
          glm::vec4 on_near = inverse * glm::vec4(ndc_x, ndc_y, gfx::kDepthNear, 1.0f);
          const glm::vec3 ray = glm::vec3(on_near) / on_near.w / near_plane;  // the point at view depth 1
          for (const float depth : {d0, d1}) {
            lo = glm::min(lo, ray * depth);
            hi = glm::max(hi, ray * depth);
          }
        }
        boxes_[(z * dims_.y + y) * dims_.x + x] = {glm::vec4(lo, 0.0f), glm::vec4(hi, 0.0f)};
      }
    }
  }
  glNamedBufferSubData(bounds_.id(), 0, static_cast<GLsizeiptr>(boxes_.size() * sizeof(ClusterBox)), boxes_.data());
}

std::uint32_t ClusterGrid::slice_of(float view_depth) const {
  if (view_depth <= uniforms_.slicing.x) return 0;
  const float x = slicing_ == ZSlicing::Uniform ? view_depth : std::log(view_depth);
  const float slice = x * uniforms_.slicing.y + uniforms_.slicing.z;
  return static_cast<std::uint32_t>(std::clamp(slice, 1.0f, static_cast<float>(dims_.z - 1)));
}

void ClusterGrid::assign(const LightAssignmentPrograms& programs, std::uint32_t light_count, GLuint per_cluster) {
  list_.assign(light_count, programs, [&] {
    glBindBufferBase(GL_UNIFORM_BUFFER, render::kClusterUniformBinding, uniform_buffer_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBoundsBinding, bounds_.id());
    if (per_cluster) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, render::kPerClusterBinding, per_cluster);
  });
}

void ClusterGrid::bind() const {
  glBindBufferBase(GL_UNIFORM_BUFFER, render::kClusterUniformBinding, uniform_buffer_.id());
  list_.bind();
}

std::vector<std::vector<std::uint32_t>> ClusterGrid::assign_on_cpu(std::span<const render::GpuLight> lights, const glm::mat4& view) const {
  std::vector<std::vector<std::uint32_t>> lists(cluster_count());
  for (std::uint32_t l = 0; l < lights.size(); ++l) {
    const render::GpuLight& light = lights[l];
    const bool everywhere = light.color_kind.w == static_cast<float>(render::GpuLightKind::Directional);
    const glm::vec3 centre(view * glm::vec4(glm::vec3(light.position_radius), 1.0f));
    const float radius = light.position_radius.w;
    for (std::uint32_t c = 0; c < cluster_count(); ++c) {
      const glm::vec3 nearest = glm::clamp(centre, glm::vec3(boxes_[c].lo), glm::vec3(boxes_[c].hi)) - centre;
      if (everywhere || glm::dot(nearest, nearest) <= radius * radius) lists[c].push_back(l);
    }
  }
  return lists;
}

}  // namespace atrium::lighting
