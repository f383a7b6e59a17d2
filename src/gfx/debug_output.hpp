// KHR_debug output: the driver reports GL errors (and other messages) through a
// synchronous callback, so the message arrives inside the call that caused it.
// Errors are counted; tests fail when the count moves.
#pragma once

#include <cstdint>
#include <string>

namespace atrium::gfx {

// Installs the callback on the current context. Needs a debug context to see
// everything; a non-debug context still reports what the driver chooses to.
void enable_debug_output();

[[nodiscard]] std::uint64_t gl_error_count();
[[nodiscard]] std::string last_gl_error();
void reset_gl_error_count();

}  // namespace atrium::gfx
