#include "app/demo_keys.hpp"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "assets/scene_file.hpp"
#include "components/camera.hpp"
#include "components/demo.hpp"
#include "components/frame_resources.hpp"
#include "components/input.hpp"
#include "components/light.hpp"
#include "components/transform.hpp"
#include "render/techniques/technique.hpp"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace atrium {
namespace {

// The name `step` places after `current` in `names`, wrapping around.
std::string step_name(const std::vector<std::string>& names, const std::string& current, int step) {
  const auto count = static_cast<int>(names.size());
  const auto found = std::find(names.begin(), names.end(), current);
  const int index = found == names.end() ? 0 : static_cast<int>(found - names.begin());
  return names[static_cast<std::size_t>(((index + step) % count + count) % count)];
}

void set_debug_view(World& world, const std::string& view) {
  world.registry().resource<RendererSettings>().debug_view = view;
  say("debug view: " + (view.empty() ? std::string("off") : view));
}

void request_view(World& world, int view) { world.registry().resource<DemoRequests>().view = view; }

constexpr std::array kDemoKeys{
    DemoKey{{GLFW_KEY_T, 0}, "t / Shift+t", "next / previous lighting mode",
            [](World& world, bool shift) {
              world.registry().resource<DemoRequests>().mode = step_name(world.modes(), world.mode(), shift ? -1 : 1);
            }},
    DemoKey{{GLFW_KEY_1, 0}, "1..5", "stored views", [](World& world, bool) { request_view(world, 1); }},
    DemoKey{{GLFW_KEY_2, 0}, "", "", [](World& world, bool) { request_view(world, 2); }},
    DemoKey{{GLFW_KEY_3, 0}, "", "", [](World& world, bool) { request_view(world, 3); }},
    DemoKey{{GLFW_KEY_4, 0}, "", "", [](World& world, bool) { request_view(world, 4); }},
    DemoKey{{GLFW_KEY_5, 0}, "", "", [](World& world, bool) { request_view(world, 5); }},
    DemoKey{{GLFW_KEY_G, 0}, "g / Shift+g", "cycle debug views (G-buffer targets, depth, heatmaps, light lists)",
            [](World& world, bool shift) {
              std::vector<std::string> views{""};
              for (const render::OfferedView& view : world.renderer().offered_views()) views.push_back(view.name);
              set_debug_view(world, step_name(views, world.registry().resource<RendererSettings>().debug_view, shift ? -1 : 1));
            }},
    DemoKey{{GLFW_KEY_L, 0}, "l", "light-volume outlines on/off",
            [](World& world, bool) {
              const bool on = world.registry().resource<RendererSettings>().debug_view == "light-volumes";
              set_debug_view(world, on ? "" : "light-volumes");
            }},
    DemoKey{{GLFW_KEY_EQUAL, GLFW_KEY_KP_ADD}, "+ / -", "double / halve the light count",
            [](World& world, bool) {
              world.registry().resource<DemoRequests>().light_count = std::min(std::max(1u, world.light_count() * 2), kMaxLights);
            }},
    DemoKey{{GLFW_KEY_MINUS, GLFW_KEY_KP_SUBTRACT}, "", "",
            [](World& world, bool) { world.registry().resource<DemoRequests>().light_count = world.light_count() / 2; }},
    DemoKey{{GLFW_KEY_P, 0}, "p", "pause / resume the light animation (generated lights move; the built-in scene's lamps do not)",
            [](World& world, bool) {
              bool& paused = world.registry().resource<LightAnimationSettings>().paused;
              paused = !paused;
              // The built-in scene's first lights are its lamps', which stay put.
              const bool none_moves = world.registry().count<LightAnimation>() == 0;
              say(std::string(paused ? "light animation: paused" : "light animation: running") +
                  (none_moves ? " (no light here moves: generated lights do, and + adds them)" : ""));
            }},
    // Where the camera is, as a scene-file view line and a --camera value, so
    // that users can author views by flying to them.
    DemoKey{{GLFW_KEY_C, 0}, "c", "the camera as a scene-file view line and a --camera value",
            [](World& world, bool) {
              if (const auto here = camera_here(world)) {
                say("camera: --camera " + assets::camera_argument(*here) + "  view: " + assets::view_json(*here));
              }
            }},
};

}  // namespace

std::span<const DemoKey> demo_keys() { return kDemoKeys; }

std::optional<assets::NamedView> camera_here(World& world) {
  std::optional<assets::NamedView> here;
  world.registry().view<Transform, Camera, CameraAngles>().each([&](const Transform& t, const Camera&, const CameraAngles& angles) {
    here = assets::NamedView{"here", t.position, angles.yaw_degrees, angles.pitch_degrees};
  });
  return here;
}

std::string key_help_line(std::string_view keys, std::string_view help) {
  std::string line(keys);
  line.resize(std::max<std::size_t>(line.size() + 1, 14), ' ');
  return line + std::string(help) + "\n";
}

const std::string& window_key_help() {
  static const std::string kHelp = demo_key_help() + key_help_line("b", "quick benchmark of every mode from here (printed to stdout)") +
                                   key_help_line("F12", "screenshot (PNG in the working folder)") +
                                   key_help_line("r", "reload shaders (a failing one keeps its old version)") +
                                   key_help_line("v", "vsync on/off") + key_help_line("F1", "hide / show this overlay") +
                                   key_help_line("h", "key help") + key_help_line("Esc", "quit");
  return kHelp;
}

std::string demo_key_help() {
  std::string text = key_help_line("w/s a/d q/e", "fly forward/back, left/right, down/up (Shift: faster)") +
                     key_help_line("mouse drag", "look around (arrow keys: turn); scroll: flying speed");
  for (const DemoKey& row : kDemoKeys) {
    if (!row.label.empty()) text += key_help_line(row.label, row.help);
  }
  return text;
}

void say(const std::string& line) {
  std::printf("%s\n", line.c_str());
  std::fflush(stdout);
}

void apply_demo_keys(World& world) {
  const InputState& input = world.registry().resource<InputState>();
  if (input.ui_wants_keyboard) return;
  for (const KeyPress& press : input.pressed) {
    for (const DemoKey& row : kDemoKeys) {
      if (press.key == row.keys[0] || (row.keys[1] != 0 && press.key == row.keys[1])) row.act(world, (press.mods & GLFW_MOD_SHIFT) != 0);
    }
  }
}

void carry_out_demo_requests(World& world) {
  auto& requests = world.registry().resource<DemoRequests>();
  if (requests.mode) {
    world.set_mode(*requests.mode);
    say("mode: " + world.mode());
  }
  if (requests.view && *requests.view <= static_cast<int>(world.scene().views.size())) {
    world.set_view(*requests.view);
    say("view: " + std::to_string(world.view()) + " " + world.scene().views[static_cast<std::size_t>(world.view() - 1)].name);
  }
  if (requests.light_count) {
    world.set_light_count(*requests.light_count);
    say("lights: " + std::to_string(world.light_count()));
  }
  requests.mode.reset();
  requests.view.reset();
  requests.light_count.reset();
}

}  // namespace atrium
