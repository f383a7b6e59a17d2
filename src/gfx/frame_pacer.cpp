#include "gfx/frame_pacer.hpp"

#include <chrono>

#include "gfx/gl_features.hpp"

namespace atrium::gfx {

void FramePacer::begin_frame() {
  waited_ms_ = 0.0;
  if (!gl_features().finish_waits) return;
  const auto start = std::chrono::steady_clock::now();
  if (ends_[frame_ % kFramesInFlight].wait_uncounted()) {
    waited_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  }
}

void FramePacer::end_frame() {
  if (gl_features().finish_waits) {
    ends_[frame_ % kFramesInFlight].place();
    // Submits the frame: a headless loop has no buffer swap to do it, and the
    // GPU would otherwise idle until the driver's command buffer filled.
    glFlush();
  }
  ++frame_;
}

}  // namespace atrium::gfx
