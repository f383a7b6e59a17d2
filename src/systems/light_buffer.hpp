// The LightBuffer system (Render phase, before the MeshRenderer): mirrors every
// light entity (Transform + LightColor; optional LightRadius, SpotCone,
// DirectionalLight) into one shader storage buffer each frame. The buffer grows
// geometrically; there is no cap.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "ecs/scheduler.hpp"
#include "gfx/gl_object.hpp"

namespace atrium {

enum class GpuLightKind : std::uint32_t { Point = 0, Spot = 1, Directional = 2 };

// std430 twin of Light in shaders/common/lights.glsl.
struct GpuLight {
  glm::vec4 position_radius;  // xyz position, w radius (directional: 0)
  glm::vec4 color_kind;       // rgb colour * intensity, w GpuLightKind
  glm::vec4 direction;        // xyz where the light points (spot, directional)
  glm::vec4 spot;             // x = 1 / (cos inner - cos outer), y = -cos outer * x
};
static_assert(sizeof(GpuLight) == 64, "must match Light in shaders/common/lights.glsl");

struct LightBuffer {
  gfx::Buffer buffer;
  std::size_t capacity = 0;  // lights the buffer can hold
  std::uint32_t count = 0;   // lights written this frame
  std::vector<GpuLight> staging;
};

// Collects the lights of the registry in GPU layout (radius derived when absent).
[[nodiscard]] std::vector<GpuLight> gather_lights(ecs::Registry& registry);

void register_light_buffer(ecs::Scheduler& scheduler);

}  // namespace atrium
