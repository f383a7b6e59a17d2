#version 450 core
// Copies u_words 32-bit words of a buffer into a slot of a readback ring
// (gfx/readback_ring.hpp) as a shader's writes. A buffer copy into memory the
// CPU reads made NVIDIA's driver wait, on the CPU, for every command before it
// (2-6 ms a frame on an H200); a shader's writes are queued like any other work.
layout(local_size_x = 64) in;

layout(std430, binding = 22) readonly buffer ReadbackSource { uint u_source[]; };
layout(std430, binding = 23) writeonly buffer ReadbackSlot { uint u_slot[]; };

uniform uint u_source_word;  // where the copy starts in the source
uniform uint u_slot_word;    // where the slot starts in the ring
uniform uint u_words;

void main() {
  const uint i = gl_GlobalInvocationID.x;
  if (i < u_words) u_slot[u_slot_word + i] = u_source[u_source_word + i];
}
