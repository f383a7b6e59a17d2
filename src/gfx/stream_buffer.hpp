// A buffer a pass refills every frame: it grows (doubling) to hold the largest
// upload so far and is never shrunk, so a steady frame allocates nothing.
//
// An upload never writes into a buffer that commands already submitted may
// still read: a driver must then wait for the GPU to finish them, or copy the
// data aside first (on an H200 the light lists' uploads made the CPU wait for
// the GPU so: docs/benchmarks.md). Where the context has
// buffer storage the CPU writes into one of kStagingCopies persistently mapped
// copies, each reused only once the GPU has copied it out (its fence), and the
// GPU copies it into the buffer in command order; elsewhere (OpenGL 4.1, ES
// 3.0, WebGL2) glBufferSubData, as the context offers no mapping.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <span>
#include <vector>

#include "gfx/frame_pacer.hpp"
#include "gfx/gl_object.hpp"

namespace atrium::gfx {

struct StreamBuffer {
  // Uploads a stream keeps apart: an upload waits (counted, gfx/gpu_waits.hpp)
  // only when the GPU is this many uploads behind, which a stream refilled
  // once a frame never is under FramePacer (one more than it lets run ahead).
  static constexpr std::size_t kStagingCopies = FramePacer::kFramesInFlight + 1;

  Buffer buffer;
  std::size_t capacity = 0;  // bytes
  // Makes or grows the buffer to hold `bytes` (for what the GPU writes); its
  // contents are undefined after it grew.
  void reserve(std::size_t bytes);
  // Copies `bytes` from `data` to the start of the buffer (made or grown first),
  // as a command: commands submitted before it read the contents before it.
  void upload(const void* data, std::size_t bytes);
  // The same for pieces laid back to back from the start (a head and an array,
  // say), each copied once: no contiguous copy of them on the CPU first.
  void upload(std::initializer_list<std::span<const std::byte>> pieces);

 private:
  // A CPU-written copy of one upload, mapped for as long as it lives.
  struct Staging {
    Buffer buffer;
    void* mapped = nullptr;
    Fence copied;  // placed after the copy out of it
  };
  std::vector<Staging> staging_;     // none, or kStagingCopies of staging_bytes_ each
  std::size_t staging_bytes_ = 0;    // the buffer's capacity when they were made
  std::size_t next_ = 0;             // the copy the next upload writes
  bool unmappable_ = false;       // the driver refused to map one: glBufferSubData from then on
  void make_staging();
};

}  // namespace atrium::gfx
