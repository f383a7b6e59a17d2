// The light animation system (Update): moves every light with a LightAnimation
// along its circle, so that the lighting changes while the user watches. Scene
// files' generated lights get one; listed lights stay where they were placed.
// Where the context runs compute shaders (LightAnimationSettings::on_gpu) it
// moves point lights on the GPU, in a pass of its own before lighting, and
// only spot and directional lights on the CPU.
#pragma once

#include "components/light.hpp"
#include "components/transform.hpp"
#include "ecs/scheduler.hpp"

namespace atrium {

// Adds the system, and its pass to the renderer's frame modules where the
// registry holds render::FrameModules. The registry must hold
// LightAnimationSettings for anything to move.
void register_light_animation(ecs::Scheduler& scheduler, ecs::Registry& registry);

}  // namespace atrium
