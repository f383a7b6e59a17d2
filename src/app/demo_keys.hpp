// The demo's keys that act on the world, one row each, shared by the window
// (src/app/window.cpp) and the page (src/app/web_main.cpp): modes, views,
// debug views, light count, pause, the camera line. Mode, view and light-count
// changes go through DemoRequests so that a front end can step back from what
// the driver refuses; the window adds its own keys (quit, screenshot,
// benchmark, reload, help, vsync, overlay).
#pragma once

#include <array>
#include <optional>
#include <span>
#include <string>

#include "app/world.hpp"
#include "assets/scene_file.hpp"

namespace atrium {

struct DemoKey {
  std::array<int, 2> keys;  // GLFW key codes; 0 where a row has one
  std::string_view label;   // the keys as the help names them; empty where the row before covers this one
  std::string_view help;
  void (*act)(World& world, bool shift);
};
[[nodiscard]] std::span<const DemoKey> demo_keys();

// The help lines of the fly camera and the demo keys ("t / Shift+t   next /
// previous lighting mode"); each front end adds its own keys' lines.
[[nodiscard]] std::string demo_key_help();
// The window's keys (demo_key_help and the window's own): `h`, --help and
// the overlay's help window.
[[nodiscard]] const std::string& window_key_help();
// One help line, aligned as demo_key_help's.
[[nodiscard]] std::string key_help_line(std::string_view keys, std::string_view help);

// Where the camera is, as a view named "here" (what `c` prints); none
// without a camera.
[[nodiscard]] std::optional<assets::NamedView> camera_here(World& world);

// Prints one line on standard output (the terminal, or the page's console).
void say(const std::string& line);

// Runs the row of every key pressed this frame (InputState::pressed) unless
// the overlay has the keyboard.
void apply_demo_keys(World& world);
// Carries out the mode, view and light-count requests, saying each change, and
// clears them.
void carry_out_demo_requests(World& world);

}  // namespace atrium
