// OpenGL 4.5 core contexts: headless through EGL (the NVIDIA/hardware EGL device
// platform when one is present, Mesa's surfaceless platform otherwise) and
// windowed through GLFW. Both make themselves current on creation and enable
// KHR_debug output when asked to (debug builds and tests do).
#pragma once

#include <memory>
#include <stdexcept>
#include <string>

struct GLFWwindow;

namespace atrium::gfx {

struct ContextOptions {
#ifdef ATRIUM_GL_DEBUG_DEFAULT
  bool debug = true;
#else
  bool debug = false;
#endif
};

class ContextError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Driver strings of the current context, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
struct ContextInfo {
  std::string vendor;
  std::string renderer;
  std::string version;
  std::string platform;  // "egl-device", "egl-surfaceless" or "glfw"
};
[[nodiscard]] ContextInfo current_context_info(std::string platform);

class HeadlessContext {
 public:
  // Throws ContextError naming what failed (no EGL, no GL 4.5 core...).
  static std::unique_ptr<HeadlessContext> create(const ContextOptions& options = {});
  ~HeadlessContext();
  HeadlessContext(const HeadlessContext&) = delete;
  HeadlessContext& operator=(const HeadlessContext&) = delete;

  [[nodiscard]] const ContextInfo& info() const { return info_; }

 private:
  HeadlessContext() = default;
  void* display_ = nullptr;
  void* context_ = nullptr;
  ContextInfo info_;
};

class WindowContext {
 public:
  // Throws ContextError when there is no display or GLFW cannot give a 4.5 core context.
  static std::unique_ptr<WindowContext> create(const std::string& title, int width, int height,
                                               const ContextOptions& options = {});
  ~WindowContext();
  WindowContext(const WindowContext&) = delete;
  WindowContext& operator=(const WindowContext&) = delete;

  [[nodiscard]] GLFWwindow* window() const { return window_; }
  [[nodiscard]] const ContextInfo& info() const { return info_; }
  void set_vsync(bool on);

 private:
  WindowContext() = default;
  GLFWwindow* window_ = nullptr;
  ContextInfo info_;
};

}  // namespace atrium::gfx
