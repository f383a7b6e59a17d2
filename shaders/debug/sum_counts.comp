#version 450 core
// Sums the debug views' per-pixel counters (the heatmap's lights evaluated,
// the fragments view's fragments) over each 16x16 block, one uint per work
// group: the C++ side (DebugViews) reads the sums a frame later and averages
// them, so the frame never waits for its counts. A block's sum fits a uint up
// to 16 million counts per pixel.
layout(local_size_x = 16, local_size_y = 16) in;

layout(binding = 0, r32ui) uniform readonly uimage2D u_counts;
layout(std430, binding = 11) writeonly buffer BlockSums { uint u_block_sums[]; };

shared uint s_sum;

void main() {
  if (gl_LocalInvocationIndex == 0u) s_sum = 0u;
  barrier();
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (all(lessThan(pixel, imageSize(u_counts)))) atomicAdd(s_sum, imageLoad(u_counts, pixel).r);
  barrier();
  if (gl_LocalInvocationIndex == 0u) u_block_sums[gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x] = s_sum;
}
