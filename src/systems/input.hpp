// The input system (Input phase): window events collected between frames become
// the frame's InputState resource (components/input.hpp): keys pressed this
// frame, keys held, cursor movement, mouse-drag looking and scroll.
#pragma once

#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "components/input.hpp"
#include "ecs/scheduler.hpp"

struct GLFWwindow;

namespace atrium {

// One window event, as the GLFW callbacks report it.
struct InputEvent {
  enum class Kind { Key, MouseButton, Cursor, Scroll } kind = Kind::Key;
  int code = 0;    // key or mouse button
  int action = 0;  // GLFW_PRESS, GLFW_RELEASE, GLFW_REPEAT
  int mods = 0;
  glm::dvec2 value{0.0};  // Cursor: position; Scroll: offsets
  double seconds = 0.0;   // when it happened (glfwGetTime's clock)
};

// Queued by the callbacks, drained once per frame (a registry resource).
struct InputEvents {
  std::vector<InputEvent> queue;
};

// Starts a new frame of `state` taken at `now` and applies `events` (which
// happened since the previous frame's `now`) in order.
void apply_input_events(InputState& state, std::span<const InputEvent> events, double now);

// Installs GLFW callbacks on `window` that queue into the registry's
// InputEvents, and the system that applies them. Install before the overlay,
// whose backend chains to these callbacks.
void register_input(ecs::Scheduler& scheduler, ecs::Registry& registry, GLFWwindow* window);

}  // namespace atrium
