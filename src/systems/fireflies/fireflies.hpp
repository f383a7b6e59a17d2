// The fireflies demo system, the example of a system that draws
// (docs/extending.md). Its option "fireflies" (--fireflies N, a scene file's
// "systems": {"fireflies": N}, the overlay's slider) keeps N Firefly entities,
// small point lights that light the scene in every mode like any other light,
// wandering through the scene's bounds (on the light animation's clock, so
// `p` pauses them and a headless render sees them where it starts them). Its
// sprites pass draws each as a glowing sprite into the lit HDR image.
#pragma once

#include "ecs/scheduler.hpp"

namespace atrium {

// Adds the system (Update phase) and its sprites pass to the renderer's
// frame modules (after lighting). The registry must hold SystemOptions,
// SceneSettings, LightAnimationSettings and render::FrameModules.
void register_fireflies(ecs::Scheduler& scheduler, ecs::Registry& registry);

}  // namespace atrium
