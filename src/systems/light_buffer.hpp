// The LightBuffer system (Render phase, before the MeshRenderer): mirrors every
// light entity (Transform + LightColor, optional LightRadius) into one shader
// storage buffer each frame. The buffer grows geometrically; there is no cap.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "ecs/scheduler.hpp"
#include "gfx/gl_object.hpp"

namespace atrium {

// std430 twin of PointLight in shaders/common/lights.glsl.
struct GpuPointLight {
  glm::vec4 position_radius;  // xyz position, w radius
  glm::vec4 color;            // rgb colour * intensity
};
static_assert(sizeof(GpuPointLight) == 32, "must match PointLight in shaders/common/lights.glsl");

struct LightBuffer {
  gfx::Buffer buffer;
  std::size_t capacity = 0;  // lights the buffer can hold
  std::uint32_t count = 0;   // lights written this frame
  std::vector<GpuPointLight> staging;
};

// Collects the lights of the registry in GPU layout (radius derived when absent).
[[nodiscard]] std::vector<GpuPointLight> gather_point_lights(ecs::Registry& registry);

void register_light_buffer(ecs::Scheduler& scheduler);

}  // namespace atrium
