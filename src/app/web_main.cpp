// The page's main (the WebAssembly build, web/): the same World the window
// runs, on a WebGL2 canvas through GLFW. The page turns its URL parameters
// into command-line options (web/shell.html: ?mode=x&view=3 is --mode x
// --view 3), which go through the command line's own parser: same values,
// same messages. The HTML panel drives the world through the atrium_*
// functions below, and twice a second each frame hands it fps and pass times.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <emscripten/emscripten.h>
#include <nlohmann/json.hpp>

#include "gfx/gl.hpp"  // before GLFW, which would bring in GL/gl.h
#include <GLFW/glfw3.h>

#include "app/cli.hpp"
#include "app/demo_keys.hpp"
#include "app/world.hpp"
#include "assets/image.hpp"
#include "assets/scene_file.hpp"
#include "components/demo.hpp"
#include "components/frame_resources.hpp"
#include "components/input.hpp"
#include "components/light.hpp"
#include "components/transform.hpp"
#include "gfx/context.hpp"
#include "gfx/limits.hpp"
#include "render/techniques/technique.hpp"
#include "systems/fly_camera.hpp"
#include "systems/input.hpp"
#include "systems/light_animation.hpp"

namespace atrium {
namespace {

struct Page {
  std::unique_ptr<gfx::WindowContext> context;
  std::unique_ptr<World> world;
  double last_seconds = 0.0;
  double stats_seconds = 0.0;
  int frames_since_stats = 0;
  std::string reply;       // what the last atrium_* call returns to the page
  std::string last_error;  // what the last frame failed with
};
Page* g_page = nullptr;

void show_error(const std::string& message) {
  std::fprintf(stderr, "atrium: %s\n", message.c_str());
  EM_ASM({ atriumShowError(UTF8ToString($0)); }, message.c_str());
}

// fps over the last half second and the latest frame's pass times, as JSON.
std::string stats_json(World& world, double fps, const std::string& refused) {
  const gfx::PassTimer& timer = world.renderer().timer();
  nlohmann::ordered_json passes = nlohmann::ordered_json::array(), views = nlohmann::ordered_json::array();
  double total = 0.0;
  for (const gfx::PassTime& pass : timer.latest()) {
    passes.push_back({{"name", pass.name}, {"ms", pass.milliseconds}});
    total += pass.milliseconds;
  }
  for (const render::OfferedView& view : world.renderer().offered_views()) views.push_back(view.name);
  const nlohmann::ordered_json stats{
      {"fps", fps},
      {"refused", refused},  // why the latest frame drew nothing; empty when it drew
      {"mode", world.mode()},
      {"lights", world.light_count()},
      {"view", world.view()},
      {"debug_view", world.registry().resource<RendererSettings>().debug_view},
      {"paused", world.registry().resource<LightAnimationSettings>().paused},
      {"timing", timer.method_name()},
      {"passes_ms", total},
      {"passes", passes},
      {"views", views},
      {"modes", world.modes()}};
  return stats.dump();
}

void frame() {
  Page& page = *g_page;
  World& world = *page.world;
  const double now = emscripten_get_now() / 1000.0;
  int width = 0, height = 0;
  glfwGetFramebufferSize(page.context->window(), &width, &height);
  if (width > 0 && height > 0) world.set_size({width, height});
  try {
    world.frame(page.last_seconds > 0.0 ? now - page.last_seconds : 0.0);
    apply_demo_keys(world);
    carry_out_demo_requests(world);
    page.last_error.clear();
  } catch (const std::exception& e) {
    // Once, not every frame: the panel's next change may cure it.
    if (page.last_error != e.what()) show_error(e.what());
    page.last_error = e.what();
  }
  page.last_seconds = now;
  ++page.frames_since_stats;
  if (now - page.stats_seconds >= 0.5) {
    const double fps = page.frames_since_stats / (now - page.stats_seconds);
    const std::string json = stats_json(world, fps, page.last_error);
    EM_ASM({ atriumShowStats(UTF8ToString($0)); }, json.c_str());
    page.stats_seconds = now;
    page.frames_since_stats = 0;
  }
}

// Waits until the GPU has drawn the frame: reading back a pixel of the canvas
// (which the frame's last pass writes) is a round trip to the GPU process.
void wait_for_frame() {
  std::uint8_t pixel[4];
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
}

// Runs `change` on the world; the reply is empty or the one-line error.
template <typename Change>
const char* apply(Change change) {
  g_page->reply.clear();
  if (!g_page->world) return "";  // it failed to start, and said why
  try {
    change(*g_page->world);
  } catch (const std::exception& e) {
    g_page->reply = e.what();
  }
  return g_page->reply.c_str();
}

// A value from the panel, parsed by the command line's own row for `option`
// (--lights, --light-radius), so that it is refused with the URL's message.
CliOptions parse_panel_value(const char* option, const char* value) {
  const std::string_view args[] = {option, value};
  return parse_cli(args);
}

}  // namespace
}  // namespace atrium

extern "C" {

EMSCRIPTEN_KEEPALIVE const char* atrium_set_mode(const char* mode) {
  return atrium::apply([&](atrium::World& world) { world.set_mode(mode); });
}

EMSCRIPTEN_KEEPALIVE const char* atrium_set_view(int view) {
  return atrium::apply([&](atrium::World& world) { world.set_view(view); });
}

EMSCRIPTEN_KEEPALIVE const char* atrium_set_lights(const char* count) {
  return atrium::apply([&](atrium::World& world) { world.set_light_count(*atrium::parse_panel_value("--lights", count).lights); });
}

// "0" (or nothing): each light keeps its own radius.
EMSCRIPTEN_KEEPALIVE const char* atrium_set_radius(const char* radius) {
  return atrium::apply([&](atrium::World& world) {
    const std::string_view text(radius);
    world.set_light_radius(text.empty() || text == "0" ? std::nullopt : atrium::parse_panel_value("--light-radius", radius).light_radius);
  });
}

EMSCRIPTEN_KEEPALIVE const char* atrium_set_debug_view(const char* view) {
  return atrium::apply([&](atrium::World& world) { world.registry().resource<atrium::RendererSettings>().debug_view = view; });
}

EMSCRIPTEN_KEEPALIVE const char* atrium_set_paused(int paused) {
  return atrium::apply([&](atrium::World& world) {
    world.registry().resource<atrium::LightAnimationSettings>().paused = paused != 0;
  });
}

// Draws every mode once from the current view and writes each picture to
// `folder`/MODE.png in the page's file system (the browser tests read them);
// the reply names the first failure, and any WebGL error.
EMSCRIPTEN_KEEPALIVE const char* atrium_capture_modes(const char* folder) {
  return atrium::apply([&](atrium::World& world) {
    std::filesystem::create_directories(folder);
    for (const std::string& mode : world.modes()) {
      world.set_mode(mode);
      world.frame(0.0);
      atrium::assets::write_png(std::filesystem::path(folder) / (mode + ".png"), world.renderer().read_output());
      if (const GLenum error = glGetError(); error != GL_NO_ERROR) {
        throw std::runtime_error("WebGL error 0x" + std::to_string(error) + " drawing " + mode);
      }
    }
  });
}

// Frame times of every mode from the current view, as JSON ({"forward":
// 12.3, ...}: the median of `frames` after `warmup`, in milliseconds, as atrium
// bench reports them). A browser's glFinish does not wait for its GPU
// process; reading a pixel of the canvas does, so each frame's time is what
// it cost the GPU as well as the CPU.
EMSCRIPTEN_KEEPALIVE const char* atrium_bench_modes(int frames, int warmup) {
  nlohmann::ordered_json medians = nlohmann::ordered_json::object();
  const char* error = atrium::apply([&](atrium::World& world) {
    for (const std::string& mode : world.modes()) {
      world.set_mode(mode);
      for (int i = 0; i < warmup; ++i) world.frame(0.0);
      atrium::wait_for_frame();
      std::vector<double> times;
      for (int i = 0; i < std::max(frames, 1); ++i) {
        const double start = emscripten_get_now();
        world.frame(0.0);
        atrium::wait_for_frame();
        times.push_back(emscripten_get_now() - start);
      }
      std::nth_element(times.begin(), times.begin() + static_cast<std::ptrdiff_t>(times.size() / 2), times.end());
      medians[mode] = times[times.size() / 2];
    }
  });
  if (*error) return error;
  atrium::g_page->reply = medians.dump();
  return atrium::g_page->reply.c_str();
}

}  // extern "C"

int main(int argc, char** argv) {
  using namespace atrium;
  g_page = new Page();
  try {
    const std::vector<std::string_view> args(argv + 1, argv + argc);
    const CliOptions options = parse_cli(args);
    g_page->context = gfx::WindowContext::create("Atrium", options.size.x, options.size.y, {.api = options.gl_api});
    g_page->world = std::make_unique<World>(world_options(options));
    World& world = *g_page->world;
    world.registry().resource<RendererSettings>().present_to_window = true;
    register_input(world.scheduler(), world.registry(), g_page->context->window());
    register_fly_camera(world.scheduler());
    register_light_animation(world.scheduler());
    world.registry().set_resource<DemoRequests>();
    std::printf("Atrium on %s (%s), %s, %u lights\n", g_page->context->info().api.c_str(),
                g_page->context->info().renderer.c_str(), world.mode().c_str(), world.light_count());
  } catch (const std::exception& e) {
    show_error(e.what());
    EM_ASM({ atriumShowRefused(UTF8ToString($0)); }, e.what());
    g_page->world.reset();
    return kExitUsage;
  }
  g_page->stats_seconds = emscripten_get_now() / 1000.0;
  emscripten_set_main_loop(frame, 0, false);
  return kExitOk;
}
