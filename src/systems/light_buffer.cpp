#include "systems/light_buffer.hpp"

#include <algorithm>
#include <cmath>

#include "components/light.hpp"
#include "components/transform.hpp"
#include "systems/lighting/light_falloff.hpp"

namespace atrium {

std::vector<GpuLight> gather_lights(ecs::Registry& registry) {
  std::vector<GpuLight> lights;
  lights.reserve(registry.count<LightColor>());
  registry.view<Transform, LightColor>().each([&](ecs::Entity entity, const Transform& transform, const LightColor& light) {
    const LightRadius* radius = registry.try_get<LightRadius>(entity);
    const SpotCone* cone = registry.try_get<SpotCone>(entity);
    const bool directional = registry.has<DirectionalLight>(entity);
    GpuLightKind kind = directional ? GpuLightKind::Directional : cone ? GpuLightKind::Spot : GpuLightKind::Point;
    const float r = directional ? 0.0f : radius ? radius->radius : lighting::light_radius_from_intensity(light.color, light.intensity);
    GpuLight gpu{glm::vec4(transform.position, r), glm::vec4(light.color * light.intensity, static_cast<float>(kind)),
                 glm::vec4(transform.rotation * glm::vec3(0.0f, 0.0f, -1.0f), 0.0f), glm::vec4(0.0f)};
    if (cone) {
      // glTF's smooth spot falloff: clamp(cos * scale + offset, 0, 1)^2.
      const float cos_outer = std::cos(cone->outer_cone), cos_inner = std::cos(cone->inner_cone);
      const float scale = 1.0f / std::max(cos_inner - cos_outer, 1e-4f);
      gpu.spot = glm::vec4(scale, -cos_outer * scale, 0.0f, 0.0f);
    }
    lights.push_back(gpu);
  });
  return lights;
}

void register_light_buffer(ecs::Scheduler& scheduler) {
  scheduler.add(ecs::Phase::Render, "light_buffer", [](ecs::Registry& registry) {
    LightBuffer* state = registry.try_resource<LightBuffer>();
    if (!state) state = &registry.set_resource<LightBuffer>();
    state->staging = gather_lights(registry);
    state->count = static_cast<std::uint32_t>(state->staging.size());
    const std::size_t needed = std::max<std::size_t>(state->staging.size(), 1);
    if (!state->buffer || needed > state->capacity) {
      state->capacity = std::max(needed, state->capacity * 2);
      state->buffer = gfx::create_buffer();
      glNamedBufferData(state->buffer.id(), static_cast<GLsizeiptr>(state->capacity * sizeof(GpuLight)), nullptr, GL_DYNAMIC_DRAW);
    }
    if (!state->staging.empty()) {
      glNamedBufferSubData(state->buffer.id(), 0, static_cast<GLsizeiptr>(state->staging.size() * sizeof(GpuLight)),
                           state->staging.data());
    }
  });
}

}  // namespace atrium
