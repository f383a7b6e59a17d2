// The GL 4.5 entry points Atrium calls (direct state access, program uniforms,
// multi-bind, clip control...) built from OpenGL 4.1 / ES 3.0 calls, for
// contexts that lack them: the engine keeps one way of talking to GL, and a
// context without DSA edits each object by binding it to a target no draw
// reads (texture unit kEditUnit, GL_COPY_WRITE_BUFFER; framebuffer, vertex
// array and program bindings are put back). Nothing is routed where the
// context has the real entry point, so the full tier runs the driver's own.
#pragma once

#include "gfx/gl_features.hpp"

namespace atrium::gfx {

// The texture unit edits bind to: the last of the 32 every ES 3.0 context has,
// above every unit a pass samples from.
inline constexpr unsigned kEditUnit = 31;

// Points each entry point the context lacks at its emulation, and every other
// back at the driver's (a later context may have what an earlier one lacked).
void route_missing_entry_points(const GlFeatures& features);

}  // namespace atrium::gfx
