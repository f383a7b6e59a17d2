// The one place that includes the GL loader; libepoxy resolves entry points for
// both EGL (headless) and GLX (GLFW window) contexts. The WebAssembly build
// uses epoxy's header with a table of its own, filled from WebGL2
// (gfx/web_gl.cpp).
#pragma once

#include <epoxy/gl.h>

namespace atrium::gfx {
#ifdef __EMSCRIPTEN__
void load_entry_points();  // gfx/web_gl.cpp
#else
inline void load_entry_points() {}  // epoxy resolves each entry point on its first call
#endif
}  // namespace atrium::gfx
