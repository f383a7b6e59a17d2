// Sanitizer builds only: LeakSanitizer checks for leaks after Mesa has unloaded
// its driver at exit, so leaks inside the driver show up as "<unknown module>"
// and cannot be told apart from ours. Pinning the loaded GL driver modules keeps
// their symbols, and tests/lsan.supp then suppresses leaks inside them alone.
#pragma once

namespace atrium::gfx {

// No-op unless built with ATRIUM_SANITIZE. Call after a context is created.
void keep_gl_driver_loaded();

}  // namespace atrium::gfx
