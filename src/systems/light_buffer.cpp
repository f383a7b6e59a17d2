#include "systems/light_buffer.hpp"

#include <algorithm>

#include "components/light.hpp"
#include "components/transform.hpp"
#include "systems/lighting/light_falloff.hpp"

namespace atrium {

std::vector<GpuPointLight> gather_point_lights(ecs::Registry& registry) {
  std::vector<GpuPointLight> lights;
  lights.reserve(registry.count<LightColor>());
  registry.view<Transform, LightColor>().each([&](ecs::Entity entity, const Transform& transform, const LightColor& light) {
    const LightRadius* radius = registry.try_get<LightRadius>(entity);
    const float r = radius ? radius->radius : lighting::light_radius_from_intensity(light.color, light.intensity);
    lights.push_back({glm::vec4(transform.position, r), glm::vec4(light.color * light.intensity, 0.0f)});
  });
  return lights;
}

void register_light_buffer(ecs::Scheduler& scheduler) {
  scheduler.add(ecs::Phase::Render, "light_buffer", [](ecs::Registry& registry) {
    LightBuffer* state = registry.try_resource<LightBuffer>();
    if (!state) state = &registry.set_resource<LightBuffer>();
    state->staging = gather_point_lights(registry);
    state->count = static_cast<std::uint32_t>(state->staging.size());
    const std::size_t needed = std::max<std::size_t>(state->staging.size(), 1);
    if (!state->buffer || needed > state->capacity) {
      state->capacity = std::max(needed, state->capacity * 2);
      state->buffer = gfx::create_buffer();
      glNamedBufferData(state->buffer.id(), static_cast<GLsizeiptr>(state->capacity * sizeof(GpuPointLight)), nullptr, GL_DYNAMIC_DRAW);
    }
    if (!state->staging.empty()) {
      glNamedBufferSubData(state->buffer.id(), 0, static_cast<GLsizeiptr>(state->staging.size() * sizeof(GpuPointLight)),
                           state->staging.data());
    }
  });
}

}  // namespace atrium
