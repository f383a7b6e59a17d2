// What the GPU writes for the CPU to read a frame or more later, without ever
// waiting: each copy goes to a slot of a persistently mapped buffer with a
// fence (a plain buffer read after its fence where persistent mapping is
// missing), and poll() hands back the copies whose fences have passed (asked with
// timeout 0), oldest first. Where the context has compute shaders a shader
// writes the slot (shaders/common/readback_copy.comp): on an H200 a buffer copy
// into the ring made the CPU wait for the GPU to reach it. A copy asked for
// while every slot is still in flight is dropped: the GPU is that many frames
// behind, and the next one will do. Used by the light lists (their totals),
// occlusion culling (its counts) and the debug views' averages; one-shot
// commands wait for the GPU first (MeshRenderer::settle) and then poll.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "gfx/frame_pacer.hpp"
#include "gfx/gl_object.hpp"
#include "gfx/shader_program.hpp"

namespace atrium::gfx {

// The storage slots of readback_copy.comp (render/binding_slots.hpp lists them with the frame's).
inline constexpr unsigned kReadbackSourceBinding = 22, kReadbackSlotBinding = 23;

class ReadbackRing {
 public:
  // Twice the frames FramePacer lets run ahead: a copy a frame never finds
  // every slot in flight, and a page, where requestAnimationFrame sets the
  // pace instead, may fall as far behind again.
  static constexpr std::size_t kDefaultSlots = 2 * FramePacer::kFramesInFlight;

  // Slots of `slot_bytes` each.
  explicit ReadbackRing(std::size_t slot_bytes, std::size_t slots = kDefaultSlots);
  ~ReadbackRing();
  ReadbackRing(const ReadbackRing&) = delete;
  ReadbackRing& operator=(const ReadbackRing&) = delete;

  // Copies `bytes` (at most the slot size) of `buffer` from `offset` once the
  // commands before it have run, keeping `tag` with it (what the caller needs
  // to read it: the capacity it ran with, a count). False when it was dropped.
  // Shader writes to `buffer` before it need no barrier from the caller; the
  // current program stays current.
  bool copy(GLuint buffer, GLintptr offset, std::size_t bytes, std::uint64_t tag);
  // Calls `arrived` for every copy whose fence has passed, oldest first.
  void poll(const std::function<void(const void* data, std::size_t bytes, std::uint64_t tag)>& arrived);
  [[nodiscard]] std::size_t slot_bytes() const { return slot_bytes_; }

 private:
  struct Slot {
    Fence fence;  // placed while the copy is in flight
    std::size_t bytes = 0;
    std::uint64_t tag = 0;
    std::uint64_t order = 0;  // when it was copied, to hand slots back oldest first
  };
  std::size_t slot_bytes_;
  Buffer buffer_;
  const unsigned char* mapped_ = nullptr;     // persistently mapped where the context can
  std::vector<unsigned char> staging_;        // else where a slot is read into
  std::vector<Slot> slots_;
  std::size_t next_ = 0;
  std::uint64_t copies_ = 0;
  ShaderProgram copy_program_;  // readback_copy.comp, where the context has compute shaders
};

}  // namespace atrium::gfx
