#include <cstdlib>
#include <cstring>
#include <string_view>
#include <vector>

#include <epoxy/egl.h>

#include "gfx/context.hpp"
#include "gfx/gl.hpp"

namespace atrium::gfx {
namespace {

bool has_extension(const char* list, std::string_view name) {
  if (!list) return false;
  std::string_view rest(list);
  while (!rest.empty()) {
    const auto space = rest.find(' ');
    if (rest.substr(0, space) == name) return true;
    if (space == std::string_view::npos) break;
    rest.remove_prefix(space + 1);
  }
  return false;
}

struct Display {
  EGLDisplay handle = EGL_NO_DISPLAY;
  std::string platform;
};

// A hardware EGL device (NVIDIA's driver exposes one per GPU); Mesa's software
// device is skipped so that the surfaceless platform picks the best Mesa driver.
Display open_device_display(const char* client_extensions) {
  if (!has_extension(client_extensions, "EGL_EXT_platform_device") ||
      !has_extension(client_extensions, "EGL_EXT_device_enumeration")) {
    return {};
  }
  EGLint count = 0;
  if (!eglQueryDevicesEXT(0, nullptr, &count) || count <= 0) return {};
  std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count));
  eglQueryDevicesEXT(count, devices.data(), &count);
  for (EGLDeviceEXT device : devices) {
    const char* extensions = eglQueryDeviceStringEXT(device, EGL_EXTENSIONS);
    if (has_extension(extensions, "EGL_MESA_device_software")) continue;
    EGLDisplay display = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
    if (display == EGL_NO_DISPLAY) continue;
    if (eglInitialize(display, nullptr, nullptr)) return {display, "egl-device"};
  }
  return {};
}

Display open_surfaceless_display(const char* client_extensions) {
  if (!has_extension(client_extensions, "EGL_MESA_platform_surfaceless")) return {};
  EGLDisplay display = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (display == EGL_NO_DISPLAY || !eglInitialize(display, nullptr, nullptr)) return {};
  return {display, "egl-surfaceless"};
}

// A context of the kind `request` names, or EGL_NO_CONTEXT where the driver has none.
EGLContext create_context(EGLDisplay display, const GlVersionRequest& request, bool debug) {
  if (!eglBindAPI(request.es ? EGL_OPENGL_ES_API : EGL_OPENGL_API)) return EGL_NO_CONTEXT;
  // No surface is ever created: any surface type will do (the default asks for windows).
  const EGLint config_attributes[] = {EGL_RENDERABLE_TYPE, request.es ? EGL_OPENGL_ES3_BIT : EGL_OPENGL_BIT,
                                      EGL_SURFACE_TYPE, 0, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint config_count = 0;
  if (!eglChooseConfig(display, config_attributes, &config, 1, &config_count) || config_count == 0) return EGL_NO_CONTEXT;
  std::vector<EGLint> attributes{EGL_CONTEXT_MAJOR_VERSION, request.major, EGL_CONTEXT_MINOR_VERSION, request.minor,
                                 EGL_CONTEXT_OPENGL_DEBUG, debug ? EGL_TRUE : EGL_FALSE};
  if (!request.es) attributes.insert(attributes.end(), {EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT});
  attributes.push_back(EGL_NONE);
  return eglCreateContext(display, config, EGL_NO_CONTEXT, attributes.data());
}

}  // namespace

std::unique_ptr<HeadlessContext> HeadlessContext::create(const ContextOptions& options) {
  const char* client_extensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!client_extensions) throw ContextError("EGL: no client extensions; is libEGL (libegl1) installed?");

  // ATRIUM_EGL_PLATFORM=surfaceless|device forces one platform.
  const char* forced = std::getenv("ATRIUM_EGL_PLATFORM");
  const std::string_view force = forced ? forced : "";
  Display display;
  if (force != "surfaceless") display = open_device_display(client_extensions);
  if (display.handle == EGL_NO_DISPLAY && force != "device") display = open_surfaceless_display(client_extensions);
  if (display.handle == EGL_NO_DISPLAY) {
    throw ContextError("EGL: no usable display (tried the device and Mesa surfaceless platforms)");
  }

  auto context = std::unique_ptr<HeadlessContext>(new HeadlessContext());
  context->display_ = display.handle;

  for (const GlVersionRequest& request : gl_version_requests(options.api)) {
    context->context_ = create_context(display.handle, request, options.debug);
    if (context->context_ != EGL_NO_CONTEXT) break;
  }
  if (context->context_ == EGL_NO_CONTEXT) {
    throw ContextError("EGL: the driver gives none of " + describe_requests(options.api) +
                       " (Mesa 20 or newer has them all)");
  }
  if (!eglMakeCurrent(display.handle, EGL_NO_SURFACE, EGL_NO_SURFACE, context->context_)) {
    throw ContextError("EGL: cannot make the context current without a surface (EGL_KHR_surfaceless_context)");
  }
  detail::prepare_current_context(options);
  context->info_ = current_context_info(display.platform);
  return context;
}

HeadlessContext::~HeadlessContext() {
  if (display_) {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (context_) eglDestroyContext(display_, context_);
    eglTerminate(display_);
  }
}

}  // namespace atrium::gfx
