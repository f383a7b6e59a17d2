// The demo's keys that act on the world, one row each, shared by the window
// (src/app/window.cpp) and the page (src/app/web_main.cpp): modes, views,
// debug views, light count, pause, the camera line. Mode, view and light-count
// changes go through DemoRequests so that a front end can step back from what
// the driver refuses; the window adds its own keys (quit, screenshot,
// benchmark, reload, help, vsync, overlay).
#pragma once

#include <array>
#include <span>
#include <string>

#include "app/world.hpp"

namespace atrium {

struct DemoKey {
  std::array<int, 2> keys;  // GLFW key codes; 0 where a row has one
  void (*act)(World& world, bool shift);
};
[[nodiscard]] std::span<const DemoKey> demo_keys();

// Prints one line on standard output (the terminal, or the page's console).
void say(const std::string& line);

// Runs the row of every key pressed this frame (InputState::pressed) unless
// the overlay has the keyboard.
void apply_demo_keys(World& world);
// Carries out the mode, view and light-count requests, saying each change, and
// clears them.
void carry_out_demo_requests(World& world);

}  // namespace atrium
