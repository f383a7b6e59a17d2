#include <cstdlib>
#include <string>

#include "gfx/gl.hpp"
#include <GLFW/glfw3.h>

#include "gfx/context.hpp"
#include "gfx/debug_output.hpp"
#include "gfx/sanitizer_support.hpp"

namespace atrium::gfx {

std::unique_ptr<WindowContext> WindowContext::create(const std::string& title, int width, int height,
                                                     const ContextOptions& options) {
  const char* x11 = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  if ((!x11 || !*x11) && (!wayland || !*wayland)) {
    throw ContextError(
        "no display: run headless with `atrium render --out frame.png`, or start the window under "
        "`xvfb-run -a ./run.sh`");
  }
  if (!glfwInit()) throw ContextError("GLFW could not initialise the display connection");
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, options.debug ? GLFW_TRUE : GLFW_FALSE);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
  GLFWwindow* window = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window) {
    glfwTerminate();
    throw ContextError("GLFW could not open a window with an OpenGL 4.5 core context");
  }
  glfwMakeContextCurrent(window);
  auto context = std::unique_ptr<WindowContext>(new WindowContext());
  context->window_ = window;
  context->set_vsync(true);
  keep_gl_driver_loaded();
  if (options.debug) enable_debug_output();
  context->info_ = current_context_info("glfw");
  return context;
}

WindowContext::~WindowContext() {
  if (window_) glfwDestroyWindow(window_);
  glfwTerminate();
}

void WindowContext::set_vsync(bool on) { glfwSwapInterval(on ? 1 : 0); }

}  // namespace atrium::gfx
