// What the user did this frame, written by the input system (Input phase) from
// window events and read by the systems that react to it. Key and button codes
// are GLFW's (GLFW_KEY_*, GLFW_MOD_*), the one windowing library Atrium uses.
#pragma once

#include <bitset>
#include <vector>

#include <glm/glm.hpp>

namespace atrium {

struct KeyPress {
  int key = 0;
  int mods = 0;  // GLFW_MOD_SHIFT, ... held when the key went down
};

struct InputState {
  std::vector<KeyPress> pressed;  // keys that went down this frame, in order (no auto-repeat)
  std::bitset<512> held;          // keys down now, indexed by key code
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
