#include "systems/light_radius.hpp"

#include <vector>

#include "components/light.hpp"
#include "render/lighting/light_falloff.hpp"

namespace atrium {

void set_light_radius(ecs::Registry& registry, ecs::Entity light, float radius) {
  if (registry.has<DirectionalLight>(light)) return;
  LightColor& color = registry.get<LightColor>(light);
  color.intensity = lighting::intensity_for_radius(color.color, radius);
  registry.add<LightRadius>(light, radius);
}

void set_every_light_radius(ecs::Registry& registry, float radius) {
  std::vector<ecs::Entity> lights;
  registry.view<LightColor>().each([&](ecs::Entity e, const LightColor&) { lights.push_back(e); });
  for (const ecs::Entity light : lights) set_light_radius(registry, light, radius);
}

}  // namespace atrium
