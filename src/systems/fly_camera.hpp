// The fly-camera system (Update): steers every camera with a FlyCamera from the
// frame's InputState. w/s forward and back, a/d left and right, q/e down and up,
// Shift faster, mouse drag or arrow keys to look, scroll wheel for speed.
#pragma once

#include "ecs/scheduler.hpp"

namespace atrium {

inline constexpr float kMaxPitchDegrees = 89.0f;
inline constexpr float kMinFlySpeed = 0.05f, kMaxFlySpeed = 500.0f;

void register_fly_camera(ecs::Scheduler& scheduler);

}  // namespace atrium
