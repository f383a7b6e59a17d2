// One radius for point and spot lights, the same way wherever it is set: the
// light's LightRadius becomes `radius` and its intensity the one whose derived
// radius that is (lighting::intensity_for_radius), so brightness follows reach.
// --light-radius applies it as lights spawn, the overlay's slider live.
#pragma once

#include "ecs/registry.hpp"

namespace atrium {

// Directional lights have no radius: they are left as they are.
void set_light_radius(ecs::Registry& registry, ecs::Entity light, float radius);
// The same for every light entity (those with a LightColor).
void set_every_light_radius(ecs::Registry& registry, float radius);

}  // namespace atrium
