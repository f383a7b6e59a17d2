// std140 twin of FrameBlock in shaders/common/frame.glsl (binding 0).
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

namespace atrium::render {


struct FrameUniforms {
  glm::mat4 view;
  glm::mat4 projection;
  glm::mat4 view_projection;
  glm::mat4 inverse_view_projection;
  glm::vec4 camera_position;
  glm::vec4 ambient;
  glm::vec4 background;
  glm::vec2 viewport_size;
  float exposure;
  std::uint32_t light_count;
  float near_plane;
  float far_plane;
  glm::vec2 padding;
};
static_assert(sizeof(FrameUniforms) == 336, "must match FrameBlock in shaders/common/frame.glsl");

}  // namespace atrium::render
