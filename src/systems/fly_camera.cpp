#include "systems/fly_camera.hpp"

#include <algorithm>
#include <cmath>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "components/camera.hpp"
#include "components/input.hpp"
#include "components/transform.hpp"
#include "systems/camera.hpp"

namespace atrium {
namespace {

float axis(const InputState& input, int positive, int negative) {
  return (input.held.test(static_cast<std::size_t>(positive)) ? 1.0f : 0.0f) -
         (input.held.test(static_cast<std::size_t>(negative)) ? 1.0f : 0.0f);
}

}  // namespace

void register_fly_camera(ecs::Scheduler& scheduler) {
  scheduler.add(ecs::Phase::Update, "fly_camera", [](ecs::Registry& registry) {
    const InputState* state = registry.try_resource<InputState>();
    if (!state) return;
    const InputState& input = *state;
    const auto dt = static_cast<float>(registry.resource<ecs::FrameClock>().delta_seconds);
    registry.view<Transform, CameraAngles, FlyCamera>().each([&](Transform& transform, CameraAngles& angles, FlyCamera& fly) {
      if (!input.ui_wants_mouse) {
        if (input.looking) {
          angles.yaw_degrees += static_cast<float>(input.cursor_delta.x) * fly.look_degrees_per_pixel;
          angles.pitch_degrees -= static_cast<float>(input.cursor_delta.y) * fly.look_degrees_per_pixel;
        }
        fly.speed = std::clamp(fly.speed * std::pow(1.25f, static_cast<float>(input.scroll)), kMinFlySpeed, kMaxFlySpeed);
      }
      glm::vec3 move(0.0f);
      if (!input.ui_wants_keyboard) {
        angles.yaw_degrees += axis(input, GLFW_KEY_RIGHT, GLFW_KEY_LEFT) * fly.turn_degrees_per_second * dt;
        angles.pitch_degrees += axis(input, GLFW_KEY_UP, GLFW_KEY_DOWN) * fly.turn_degrees_per_second * dt;
        move = {axis(input, GLFW_KEY_D, GLFW_KEY_A), axis(input, GLFW_KEY_E, GLFW_KEY_Q), axis(input, GLFW_KEY_S, GLFW_KEY_W)};
      }
      angles.yaw_degrees = std::fmod(angles.yaw_degrees, 360.0f);
      angles.pitch_degrees = std::clamp(angles.pitch_degrees, -kMaxPitchDegrees, kMaxPitchDegrees);
      transform.rotation = camera_rotation(angles.yaw_degrees, angles.pitch_degrees);
      // Forward and sideways follow the view; q and e move straight down and up.
      const glm::vec3 direction = transform.rotation * glm::vec3(move.x, 0.0f, move.z) + glm::vec3(0.0f, move.y, 0.0f);
      if (glm::length(direction) == 0.0f) return;
      const bool fast = input.held.test(GLFW_KEY_LEFT_SHIFT) || input.held.test(GLFW_KEY_RIGHT_SHIFT);
      transform.position += glm::normalize(direction) * fly.speed * (fast ? fly.fast_factor : 1.0f) * dt;
    });
  });
}

}  // namespace atrium
