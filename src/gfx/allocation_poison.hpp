// Buffers allocated without data, filled with a marker word (kPoisonWord) as
// they are made. What a new buffer holds is the driver's choice: llvmpipe
// hands out zeros, NVIDIA whatever the memory held before. A pass that reads
// what nothing wrote (a count from "the last frame" in the first frame, a list
// past its end) draws right here by luck and wrong on a GPU; with poisoning
// it reads the marker here too. The test programs turn it on for every test;
// frame targets are poisoned separately, before each frame's first write
// (render/frame_graph.hpp).
#pragma once

#include <cstdint>

namespace atrium::gfx {

// 0xdeadbeef: a count or index far past any buffer, a float of -6.3e18.
inline constexpr std::uint32_t kPoisonWord = 0xdeadbeefu;

// Asks that contexts adopted from now on poison their allocations (where the
// context has direct state access, whose glClearNamedBufferData does it).
void set_allocation_poison(bool on);
// Routes glNamedBufferStorage and glNamedBufferData of the current context
// through the poisoning wrappers, or back (gl_features.cpp's adopt_current_context).
void route_allocation_poison(bool direct_state_access);

}  // namespace atrium::gfx
