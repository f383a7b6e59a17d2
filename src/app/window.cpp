// The demo window: a GLFW window that runs the World with the interactive
// systems (input, fly camera, light animation, overlay) and carries out what
// keys and overlay controls ask for between frames. Every mode, view, light
// count or debug-view change is also written to stdout as one line.
#include <chrono>
#include <cstdio>
#include <ctime>

#include "app/bench.hpp"
#include "app/cli.hpp"
#include "app/demo_keys.hpp"
#include "app/world.hpp"
#include "assets/image.hpp"
#include "components/demo.hpp"
#include "components/frame_resources.hpp"
#include "components/input.hpp"
#include "gfx/context.hpp"
#include "gfx/debug_output.hpp"
#include "gfx/gl.hpp"
#include "gfx/limits.hpp"
#include "systems/fly_camera.hpp"
#include "systems/input.hpp"
#include "systems/light_animation.hpp"
#include "systems/overlay.hpp"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace atrium {
namespace {

// The window's own keys, after the ones that act on the world (demo_keys()).
void handle_keys(World& world, gfx::WindowContext& context) {
  ecs::Registry& registry = world.registry();
  const InputState& input = registry.resource<InputState>();
  if (input.ui_wants_keyboard) return;
  apply_demo_keys(world);
  auto& requests = registry.resource<DemoRequests>();
  auto& overlay = registry.resource<OverlayState>();
  for (const KeyPress& press : input.pressed) {
    switch (press.key) {
      case GLFW_KEY_ESCAPE: glfwSetWindowShouldClose(context.window(), GLFW_TRUE); break;
      case GLFW_KEY_B: requests.benchmark = true; break;
      case GLFW_KEY_F12: requests.screenshot = true; break;
      case GLFW_KEY_R: requests.reload_shaders = true; break;
      case GLFW_KEY_H:
        overlay.show_help = !overlay.show_help;
        std::printf("%s", window_key_help().c_str());
        std::fflush(stdout);
        break;
      case GLFW_KEY_V:
        overlay.vsync = !overlay.vsync;
        context.set_vsync(overlay.vsync);
        say(overlay.vsync ? "vsync: on" : "vsync: off");
        break;
      case GLFW_KEY_F1: overlay.visible = !overlay.visible; break;
      default: break;
    }
  }
}

std::string screenshot_name() {
  const std::time_t now = std::time(nullptr);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", std::localtime(&now));
  // Several in one second get a counter.
  static int counter = 0;
  return "atrium-" + std::string(stamp) + "-" + std::to_string(counter++) + ".png";
}

// Carries out what keys and overlay asked for this frame.
void carry_out(World& world) {
  ecs::Registry& registry = world.registry();
  carry_out_demo_requests(world);
  auto& requests = registry.resource<DemoRequests>();
  auto& overlay = registry.resource<OverlayState>();
  if (requests.reload_shaders) {
    const std::vector<std::string> errors = world.reload_shaders();
    overlay.message.clear();
    for (const std::string& error : errors) {
      std::fprintf(stderr, "atrium: shader error (the old program stays):\n%s\n", error.c_str());
      overlay.message += error + "\n";
    }
    say(errors.empty() ? "shaders: reloaded" : "shaders: " + std::to_string(errors.size()) + " failed, kept their old versions");
  }
  if (requests.screenshot) {
    const std::string path = screenshot_name();
    assets::write_png(path, world.renderer().read_output());
    overlay.message = "screenshot: " + path;
    say(overlay.message);
  }
  if (requests.benchmark) {
    // Few frames: the window stands still while it runs.
    constexpr int kFrames = 8, kWarmup = 2;
    say("benchmark: every mode from the current camera, " + std::to_string(kFrames) + " frames after " + std::to_string(kWarmup) +
        " warm-up...");
    const BenchResult result = bench_current_view(world, kFrames, kWarmup);
    overlay.message = bench_markdown(result);
    say(overlay.message);
  }
  requests = {};
}

// The last mode, light count and technique options (MSAA, lighting stage...) that rendered.
struct Settings {
  std::string mode;
  std::uint32_t lights = 0;
  TechniqueOptions options;
};

// A frame asked for more than the driver allows: the window goes back to the
// settings that last rendered, or, where those are the ones refused (a larger
// window, a wider light radius), halves the lights. Only a refusal with no
// lights left ends the program.
void step_back(World& world, Settings& settled, const gfx::ResourceLimitError& e) {
  TechniqueOptions& options = world.registry().resource<RendererSettings>().technique_options;
  const bool changed = world.mode() != settled.mode || world.light_count() != settled.lights || options != settled.options;
  if (!changed && world.light_count() == 0) throw;
  if (!changed) settled.lights /= 2;
  std::fprintf(stderr, "atrium: %s\n", e.what());
  options = settled.options;
  world.set_mode(settled.mode);
  if (world.light_count() != settled.lights) world.set_light_count(settled.lights);
  const std::string line = "refused: back to " + settled.mode + " with " + std::to_string(settled.lights) + " lights";
  world.registry().resource<OverlayState>().message = std::string(e.what()) + "\n" + line;
  say(line);
}

}  // namespace

int run_window(const CliOptions& options) {
  gfx::ContextOptions context_options;
  context_options.debug = context_options.debug || options.gl_debug;
  context_options.api = options.gl_api;
  const auto context = gfx::WindowContext::create("Atrium", options.size.x, options.size.y, context_options);
  GLFWwindow* window = context->window();
  context->set_vsync(true);

  World world(world_options(options));
  world.registry().resource<RendererSettings>().present_to_window = true;
  register_input(world.scheduler(), world.registry(), window);
  register_fly_camera(world.scheduler());
  register_light_animation(world.scheduler(), world.registry());
  register_overlay(world.registry(), window);
  world.registry().resource<OverlayState>().key_help = window_key_help();
  say("renderer: " + context->info().renderer);
  say("mode: " + world.mode());
  say("view: " + std::to_string(world.view()) + " " + world.scene().views[static_cast<std::size_t>(world.view() - 1)].name);
  say("lights: " + std::to_string(world.light_count()) + " (press h for the keys)");

  Settings settled{world.mode(), world.light_count(), world.registry().resource<RendererSettings>().technique_options};
  using Clock = std::chrono::steady_clock;
  auto last = Clock::now();
  auto title_time = last;
  std::uint64_t frames = 0, frames_since_title = 0;
  while (!glfwWindowShouldClose(window)) {
    glfwPollEvents();
    int width = 0, height = 0;
    glfwGetFramebufferSize(window, &width, &height);
    if (width == 0 || height == 0) {
      // Minimised: nothing to draw; wait for events instead of spinning.
      glfwWaitEventsTimeout(0.1);
      last = Clock::now();
      continue;
    }
    world.set_size({width, height});
    const auto now = Clock::now();
    try {
      world.frame(std::chrono::duration<double>(now - last).count());
      if (frames == 0) require_offered_view(world, options.debug_view);
      settled = {world.mode(), world.light_count(), world.registry().resource<RendererSettings>().technique_options};
    } catch (const gfx::ResourceLimitError& e) {
      step_back(world, settled, e);
      continue;
    }
    last = now;
    glfwSwapBuffers(window);
    handle_keys(world, *context);
    carry_out(world);

    ++frames;
    ++frames_since_title;
    const double since_title = std::chrono::duration<double>(now - title_time).count();
    if (since_title >= 0.5) {
      // The overlay shows mode and fps; hidden, the title does.
      const bool overlay = world.registry().resource<OverlayState>().visible;
      const std::string title = overlay ? "Atrium" : "Atrium - " + world.mode() + " - " +
                                std::to_string(static_cast<int>(static_cast<double>(frames_since_title) / since_title + 0.5)) + " fps";
      glfwSetWindowTitle(window, title.c_str());
      title_time = now;
      frames_since_title = 0;
    }
    if (options.frames && frames >= *options.frames) break;
  }
  if (context_options.debug) say("GL errors: " + std::to_string(gfx::gl_error_count()));
  return kExitOk;
}

}  // namespace atrium
