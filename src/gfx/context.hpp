// OpenGL contexts: headless through EGL (the NVIDIA/hardware EGL device
// platform when one is present, Mesa's surfaceless platform otherwise) and
// windowed through GLFW. Both ask for OpenGL 4.5 core, and where the driver
// stops short of it, 4.1 core or OpenGL ES 3.0 (GlApi); both make themselves
// current on creation, learn what the context offers (gfx/gl_features.hpp) and
// enable KHR_debug output when asked to (debug builds and tests do).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

struct GLFWwindow;

namespace atrium::gfx {

// Which OpenGL a context asks for (--gl). Auto takes the first of 4.5 core,
// 4.1 core (where macOS stops) and ES 3.0 (WebGL2's feature set) the driver
// gives.
enum class GlApi : std::uint8_t { Auto, Gl45, Gl41, Es30 };
struct GlApiName {
  GlApi api;
  std::string_view name;
};
inline constexpr std::array kGlApiNames{GlApiName{GlApi::Auto, "auto"}, GlApiName{GlApi::Gl45, "4.5"},
                                        GlApiName{GlApi::Gl41, "4.1"}, GlApiName{GlApi::Es30, "es3.0"}};
[[nodiscard]] std::optional<GlApi> gl_api_from_name(std::string_view name);
[[nodiscard]] std::string_view gl_api_name(GlApi api);

// One kind of context a GlApi tries, in order.
struct GlVersionRequest {
  bool es;
  int major, minor;
};
[[nodiscard]] std::vector<GlVersionRequest> gl_version_requests(GlApi api);
// "OpenGL 4.5 core, OpenGL 4.1 core, OpenGL ES 3.0": what `api` asks for, for messages.
[[nodiscard]] std::string describe_requests(GlApi api);

struct ContextOptions {
  GlApi api = GlApi::Auto;
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
  std::string api;       // "OpenGL 4.5", "OpenGL ES 3.0"
};
[[nodiscard]] ContextInfo current_context_info(std::string platform);

namespace detail {
// After a context is made current: pins the driver for sanitizer builds, learns
// its features (routing what it lacks) and turns debug output on when asked.
void prepare_current_context(const ContextOptions& options);
}  // namespace detail

class HeadlessContext {
 public:
  // Throws ContextError naming what failed (no EGL, none of the APIs asked for...).
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
  // Throws ContextError when there is no display or GLFW gives none of the APIs asked for.
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
