#include "systems/input.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace atrium {

void apply_input_events(InputState& state, std::span<const InputEvent> events) {
  state.pressed.clear();
  state.cursor_delta = glm::dvec2(0.0);
  state.scroll = 0.0;
  for (const InputEvent& event : events) {
    switch (event.kind) {
      case InputEvent::Kind::Key: {
        if (event.code < 0 || static_cast<std::size_t>(event.code) >= state.held.size()) break;  // GLFW_KEY_UNKNOWN
        const auto key = static_cast<std::size_t>(event.code);
        if (event.action == GLFW_PRESS) {
          state.pressed.push_back({event.code, event.mods});
          state.held.set(key);
        } else if (event.action == GLFW_RELEASE) {
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
}

namespace {
void queue(GLFWwindow* window, const InputEvent& event) {
  static_cast<ecs::Registry*>(glfwGetWindowUserPointer(window))->resource<InputEvents>().queue.push_back(event);
}
}  // namespace

void register_input(ecs::Scheduler& scheduler, ecs::Registry& registry, GLFWwindow* window) {
  registry.set_resource<InputEvents>();
  registry.set_resource<InputState>();
  double x = 0.0, y = 0.0;
  glfwGetCursorPos(window, &x, &y);
  registry.resource<InputState>().cursor = {x, y};
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
    apply_input_events(r.resource<InputState>(), events.queue);
    events.queue.clear();
  });
}

}  // namespace atrium
