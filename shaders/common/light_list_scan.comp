#version 450 core
// Reads each bin's light count (light_scatter.glsl's count step), writes each
// bin's range of the light index array (exclusive prefix sums: bins follow
// each other) and turns the counts into the cursors its write step advances; also
// the longest list and the bins holding any light, and lists the bins too long for one invocation to sort
// (light_list_sort.comp). One work group: bins number thousands, not millions.
layout(local_size_x = 256) in;

#include "common/light_lists.glsl"
#include "common/light_list_sort.glsl"

layout(std430, binding = 7) buffer BinCounts { uint u_bin_counts[]; };
uniform uint u_bins;

shared uint s_sums[256];

void main() {
  uint thread = gl_LocalInvocationIndex;
  uint per_thread = (u_bins + 255u) / 256u;
  uint first = min(thread * per_thread, u_bins), end = min(first + per_thread, u_bins);
  uint sum = 0u, longest = 0u, filled = 0u;
  for (uint b = first; b < end; ++b) {
    sum += u_bin_counts[b];
    longest = max(longest, u_bin_counts[b]);
    if (u_bin_counts[b] > 0u) ++filled;
  }
  s_sums[thread] = sum;
  barrier();
  // 256 partial sums: one invocation scans them, the cheapest way at this size.
  if (thread == 0u) {
    uint running = 0u;
    for (uint t = 0u; t < 256u; ++t) {
      uint part = s_sums[t];
      s_sums[t] = running;
      running += part;
    }
  }
  barrier();
  uint offset = s_sums[thread];
  for (uint b = first; b < end; ++b) {
    uint count = u_bin_counts[b];
    u_light_ranges[b] = LightRange(offset, count);
    if (count > kShortList) u_long_bins[atomicAdd(u_long_bin_count, 1u)] = b;
    u_bin_counts[b] = offset;
    offset += count;
  }
  atomicMax(u_light_bin_max, longest);
  atomicAdd(u_light_filled_bins, filled);
  memoryBarrierBuffer();
  barrier();
  if (thread == 0u) u_long_groups.x = min(u_long_bin_count, 65535u);
}
