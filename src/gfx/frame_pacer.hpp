// Keeps the CPU at most kFramesInFlight frames ahead of the GPU. Before a
// frame is recorded, the CPU waits until the GPU has finished the frame
// kFramesInFlight before it (a fence placed at that frame's end), as a
// swapchain does for a window. Without it a GPU-bound frame loop runs ahead
// until some buffer or query ring runs out, and then waits in the middle of
// a frame, where a wait drains the queue; with it the rings never run out
// (StreamBuffer, PassTimer and ReadbackRing are sized past kFramesInFlight)
// and the one wait falls between frames with the GPU still kFramesInFlight - 1
// frames busy. That wait is the GPU setting the pace, not a stall, so it is
// reported as time (waited_ms) and not counted with gfx/gpu_waits.hpp.
#pragma once

#include <array>
#include <cstddef>

#include "gfx/gl_object.hpp"

namespace atrium::gfx {

class FramePacer {
 public:
  // Two, as most engines and drivers keep: the GPU runs one frame while the
  // CPU records the next, and no more latency than that.
  static constexpr std::size_t kFramesInFlight = 2;

  // Waits (uncounted) until the GPU has finished the frame kFramesInFlight
  // before the one about to be recorded. Not in browsers, whose
  // glClientWaitSync may not block: there requestAnimationFrame sets the pace.
  void begin_frame();
  // Marks the end of the frame just recorded.
  void end_frame();
  // How long begin_frame waited, in milliseconds: 0 unless the GPU is the bottleneck.
  [[nodiscard]] double waited_ms() const { return waited_ms_; }

 private:
  std::array<Fence, kFramesInFlight> ends_;
  std::size_t frame_ = 0;
  double waited_ms_ = 0.0;
};

}  // namespace atrium::gfx
