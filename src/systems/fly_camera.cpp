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

// Seconds `positive` was down this frame less those `negative` was: a key
// held all frame gives the frame's length, a tap its own.
float axis(const InputState& input, int positive, int negative) {
  return static_cast<float>(input.down(positive) - input.down(negative));
}

}  // namespace

void register_fly_camera(ecs::Scheduler& scheduler) {
  scheduler.add(ecs::Phase::Update, "fly_camera", [](ecs::Registry& registry) {
    const InputState* state = registry.try_resource<InputState>();
    if (!state) return;
    const InputState& input = *state;
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
        angles.yaw_degrees += axis(input, GLFW_KEY_RIGHT, GLFW_KEY_LEFT) * fly.turn_degrees_per_second;
        angles.pitch_degrees += axis(input, GLFW_KEY_UP, GLFW_KEY_DOWN) * fly.turn_degrees_per_second;
        move = {axis(input, GLFW_KEY_D, GLFW_KEY_A), axis(input, GLFW_KEY_E, GLFW_KEY_Q), axis(input, GLFW_KEY_S, GLFW_KEY_W)};
      }
      angles.yaw_degrees = std::fmod(angles.yaw_degrees, 360.0f);
      angles.pitch_degrees = std::clamp(angles.pitch_degrees, -kMaxPitchDegrees, kMaxPitchDegrees);
      transform.rotation = camera_rotation(angles.yaw_degrees, angles.pitch_degrees);
      // Forward and sideways follow the view; q and e move straight down and up.
      // Keys held together move diagonally at the same speed, for the
      // longest time any of them was down.
      const glm::vec3 direction = transform.rotation * glm::vec3(move.x, 0.0f, move.z) + glm::vec3(0.0f, move.y, 0.0f);
      const float seconds = std::max({std::abs(move.x), std::abs(move.y), std::abs(move.z)});
      if (glm::length(direction) == 0.0f) return;
      const bool fast = input.held.test(GLFW_KEY_LEFT_SHIFT) || input.held.test(GLFW_KEY_RIGHT_SHIFT) ||
                        input.down(GLFW_KEY_LEFT_SHIFT) > 0.0 || input.down(GLFW_KEY_RIGHT_SHIFT) > 0.0;
      transform.position += glm::normalize(direction) * fly.speed * (fast ? fly.fast_factor : 1.0f) * seconds;
    });
  });
}

}  // namespace atrium
