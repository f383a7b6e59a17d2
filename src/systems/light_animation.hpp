// The light animation system (Update): moves every light with a LightAnimation
// along its circle, so that the lighting changes while the user watches. Scene
// files' generated lights get one; listed lights stay where they were placed.
#pragma once

#include "components/light.hpp"
#include "components/transform.hpp"
#include "ecs/scheduler.hpp"

namespace atrium {

// Where `animation` puts its light `time` seconds in.
[[nodiscard]] glm::vec3 animated_position(const LightAnimation& animation, double time);

void register_light_animation(ecs::Scheduler& scheduler);

}  // namespace atrium
