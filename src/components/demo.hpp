// What the demo window's user asked for this frame through keys or the
// overlay, where it changes more than one component (mode, light count, view,
// shaders, a benchmark, a screenshot): the window carries these out between
// frames. Plus what the overlay shows that systems cannot know by themselves.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace atrium {

struct DemoRequests {
  std::optional<std::string> mode;
  std::optional<std::uint32_t> light_count;
  std::optional<int> view;
  bool benchmark = false;
  bool screenshot = false;
  bool reload_shaders = false;
};

struct OverlayState {
  bool visible = true;     // F1
  bool show_help = false;  // h
  bool vsync = true;       // v
  std::string message;     // the last shader error, bench table or screenshot path
  std::string key_help;    // what h shows: the front end's keys, one per line
};

}  // namespace atrium
