#include <cstdlib>
#include <string>

#include "gfx/gl.hpp"
#include <GLFW/glfw3.h>

#include "gfx/context.hpp"

namespace atrium::gfx {

std::unique_ptr<WindowContext> WindowContext::create(const std::string& title, int width, int height,
                                                     const ContextOptions& options) {
#ifndef __EMSCRIPTEN__  // the page's canvas is its display
  const char* x11 = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  if ((!x11 || !*x11) && (!wayland || !*wayland)) {
    throw ContextError(
        "no display: run headless with `atrium render --out frame.png`, or start the window under "
        "`xvfb-run -a ./run.sh`");
  }
#endif
  if (!glfwInit()) throw ContextError("GLFW could not initialise the display connection");
  GLFWwindow* window = nullptr;
  for (const GlVersionRequest& request : gl_version_requests(options.api)) {
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_CLIENT_API, request.es ? GLFW_OPENGL_ES_API : GLFW_OPENGL_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, request.major);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, request.minor);
    if (!request.es) {
      glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
      glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    }
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, options.debug ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    window = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (window) break;
  }
  if (!window) {
    glfwTerminate();
    throw ContextError("GLFW could not open a window with any of " + describe_requests(options.api));
  }
  glfwMakeContextCurrent(window);
  auto context = std::unique_ptr<WindowContext>(new WindowContext());
  context->window_ = window;
  context->set_vsync(true);
  detail::prepare_current_context(options);
  context->info_ = current_context_info("glfw");
  return context;
}

WindowContext::~WindowContext() {
  if (window_) glfwDestroyWindow(window_);
  glfwTerminate();
}

void WindowContext::set_vsync(bool on) { glfwSwapInterval(on ? 1 : 0); }

}  // namespace atrium::gfx
