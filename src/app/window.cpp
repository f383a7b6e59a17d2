// The demo window: a GLFW window that runs the World every frame and presents
// the MeshRenderer's output. Keys: 1..5 stored views, t / Shift+t modes, Esc.
#include <chrono>
#include <cstdio>

#include "app/cli.hpp"
#include "app/world.hpp"
#include "components/frame_resources.hpp"
#include "gfx/context.hpp"
#include "gfx/gl.hpp"
#include "systems/lighting/technique.hpp"
#include <GLFW/glfw3.h>

namespace atrium {
namespace {

struct KeyState {
  int pending_view = 0;
  int mode_step = 0;
};

void on_key(GLFWwindow* window, int key, int /*scancode*/, int action, int mods) {
  if (action != GLFW_PRESS) return;
  auto* state = static_cast<KeyState*>(glfwGetWindowUserPointer(window));
  if (key == GLFW_KEY_ESCAPE) glfwSetWindowShouldClose(window, GLFW_TRUE);
  if (key >= GLFW_KEY_1 && key <= GLFW_KEY_5) state->pending_view = key - GLFW_KEY_0;
  if (key == GLFW_KEY_T) state->mode_step += (mods & GLFW_MOD_SHIFT) ? -1 : 1;
}

std::string step_mode(const std::string& current, int step) {
  const auto table = lighting::technique_table();
  const auto count = static_cast<int>(table.size());
  int index = 0;
  for (int i = 0; i < count; ++i) {
    if (table[static_cast<std::size_t>(i)].name == current) index = i;
  }
  return std::string(table[static_cast<std::size_t>(((index + step) % count + count) % count)].name);
}

}  // namespace

int run_window(const CliOptions& options) {
  const auto context = gfx::WindowContext::create("Atrium", options.size.x, options.size.y);
  GLFWwindow* window = context->window();
  KeyState keys;
  glfwSetWindowUserPointer(window, &keys);
  glfwSetKeyCallback(window, on_key);

  World world(world_options(options));
  world.registry().resource<RendererSettings>().present_to_window = true;
  std::printf("renderer: %s\nmode: %s\nview: %d %s\n", context->info().renderer.c_str(), world.mode().c_str(),
              world.view(), world.scene().views[static_cast<std::size_t>(world.view() - 1)].name.c_str());
  std::fflush(stdout);

  using Clock = std::chrono::steady_clock;
  auto last = Clock::now();
  auto title_time = last;
  std::uint64_t frames = 0, frames_since_title = 0;
  while (!glfwWindowShouldClose(window)) {
    glfwPollEvents();
    if (keys.pending_view != 0) {
      if (keys.pending_view <= static_cast<int>(world.scene().views.size())) {
        world.set_view(keys.pending_view);
        std::printf("view: %d %s\n", world.view(), world.scene().views[static_cast<std::size_t>(world.view() - 1)].name.c_str());
      }
      keys.pending_view = 0;
    }
    if (keys.mode_step != 0) {
      world.set_mode(step_mode(world.mode(), keys.mode_step));
      keys.mode_step = 0;
      std::printf("mode: %s\n", world.mode().c_str());
    }
    std::fflush(stdout);

    int width = 0, height = 0;
    glfwGetFramebufferSize(window, &width, &height);
    world.set_size({width, height});
    const auto now = Clock::now();
    world.frame(std::chrono::duration<double>(now - last).count());
    last = now;
    glfwSwapBuffers(window);

    ++frames;
    ++frames_since_title;
    const double since_title = std::chrono::duration<double>(now - title_time).count();
    if (since_title >= 0.5) {
      const std::string title = "Atrium - " + world.mode() + " - " +
                                std::to_string(static_cast<int>(static_cast<double>(frames_since_title) / since_title + 0.5)) + " fps";
      glfwSetWindowTitle(window, title.c_str());
      title_time = now;
      frames_since_title = 0;
    }
    if (options.frames && frames >= *options.frames) break;
  }
  return kExitOk;
}

}  // namespace atrium
