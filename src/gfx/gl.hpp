// The one place that includes the GL loader; libepoxy resolves entry points for
// both EGL (headless) and GLX (GLFW window) contexts.
#pragma once

#include <epoxy/gl.h>
