#include "systems/input.hpp"

#include <algorithm>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace atrium {

void apply_input_events(InputState& state, std::span<const InputEvent> events, double now) {
  state.pressed.clear();
  state.cursor_delta = glm::dvec2(0.0);
  state.scroll = 0.0;
  // A key held from before this frame's span counts from its start; one
  // pressed within it, from its press.
  const double since = std::min(state.seconds, now);  // a clock set back starts afresh
  std::array<double, 512> down_from{};
  for (std::size_t key = 0; key < state.held.size(); ++key) {
    state.down_seconds[key] = 0.0;
    down_from[key] = since;
  }
  for (const InputEvent& event : events) {
    switch (event.kind) {
      case InputEvent::Kind::Key: {
        if (event.code < 0 || static_cast<std::size_t>(event.code) >= state.held.size()) break;  // GLFW_KEY_UNKNOWN
        const auto key = static_cast<std::size_t>(event.code);
        const double at = std::clamp(event.seconds, since, now);
        if (event.action == GLFW_PRESS) {
          state.pressed.push_back({event.code, event.mods});
          if (!state.held.test(key)) down_from[key] = at;
          state.held.set(key);
        } else if (event.action == GLFW_RELEASE) {
          if (state.held.test(key)) state.down_seconds[key] += at - down_from[key];
          state.held.reset(key);
        }
        break;
      }
      case InputEvent::Kind::MouseButton:
        if (event.code == GLFW_MOUSE_BUTTON_LEFT || event.code == GLFW_MOUSE_BUTTON_RIGHT) state.looking = event.action == GLFW_PRESS;
        break;
      case InputEvent::Kind::Cursor:
        state.cursor_delta += event.value - state.cursor;
        state.cursor = event.value;
        break;
      case InputEvent::Kind::Scroll:
        state.scroll += event.value.y;
        break;
    }
  }
  for (std::size_t key = 0; key < state.held.size(); ++key) {
    if (state.held.test(key)) state.down_seconds[key] += now - down_from[key];
  }
  state.seconds = now;
}

namespace {
// Each event is stamped when the window system hands it over, which is when
// it happened to within the event loop's latency, not when the frame reads it.
void queue(GLFWwindow* window, InputEvent event) {
  event.seconds = glfwGetTime();
  static_cast<ecs::Registry*>(glfwGetWindowUserPointer(window))->resource<InputEvents>().queue.push_back(event);
}
}  // namespace

void register_input(ecs::Scheduler& scheduler, ecs::Registry& registry, GLFWwindow* window) {
  registry.set_resource<InputEvents>();
  registry.set_resource<InputState>();
  double x = 0.0, y = 0.0;
  glfwGetCursorPos(window, &x, &y);
  registry.resource<InputState>().cursor = {x, y};
  registry.resource<InputState>().seconds = glfwGetTime();
  glfwSetWindowUserPointer(window, &registry);
  glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int, int action, int mods) {
    queue(w, {InputEvent::Kind::Key, key, action, mods, {}});
  });
  glfwSetMouseButtonCallback(window, [](GLFWwindow* w, int button, int action, int mods) {
    queue(w, {InputEvent::Kind::MouseButton, button, action, mods, {}});
  });
  glfwSetCursorPosCallback(window, [](GLFWwindow* w, double cx, double cy) { queue(w, {InputEvent::Kind::Cursor, 0, 0, 0, {cx, cy}}); });
  glfwSetScrollCallback(window, [](GLFWwindow* w, double sx, double sy) { queue(w, {InputEvent::Kind::Scroll, 0, 0, 0, {sx, sy}}); });
  scheduler.add(ecs::Phase::Input, "input", [](ecs::Registry& r) {
    auto& events = r.resource<InputEvents>();
    apply_input_events(r.resource<InputState>(), events.queue, glfwGetTime());
    events.queue.clear();
  });
}

}  // namespace atrium
