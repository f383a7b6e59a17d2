// What the user did this frame, written by the input system (Input phase) from
// window events and read by the systems that react to it. Key and button codes
// are GLFW's (GLFW_KEY_*, GLFW_MOD_*), the one windowing library Atrium uses.
#pragma once

#include <array>
#include <bitset>
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

namespace atrium {

struct KeyPress {
  int key = 0;
  int mods = 0;  // GLFW_MOD_SHIFT, ... held when the key went down
};

struct InputState {
  [[nodiscard]] double down(int key) const {
    return key >= 0 && static_cast<std::size_t>(key) < down_seconds.size() ? down_seconds[static_cast<std::size_t>(key)] : 0.0;
  }

  std::vector<KeyPress> pressed;  // keys that went down this frame, in order (no auto-repeat)
  std::bitset<512> held;          // keys down now, indexed by key code
  // How long each key was down since the previous frame, from the events'
  // own times: a tap or a hold that falls between two slow frames still
  // counts for its length (the fly camera moves by these, not by the frame's
  // length times "held").
  std::array<double, 512> down_seconds{};
  double seconds = 0.0;  // when this frame's input was taken (the events' clock)
  glm::dvec2 cursor{0.0};         // window pixels, origin top left
  glm::dvec2 cursor_delta{0.0};   // movement this frame
  bool looking = false;           // a mouse button is held down: drags turn the camera
  double scroll = 0.0;            // wheel steps this frame, up > 0
  // Set while the overlay has the pointer or keyboard focus: camera and key
  // systems then leave those events to it.
  bool ui_wants_mouse = false;
  bool ui_wants_keyboard = false;
};

}  // namespace atrium
