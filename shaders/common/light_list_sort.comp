#version 450 core
// Puts each bin's range of the light index array in light order after
// light_scatter.glsl's write step filled it in whatever order its atomics
// ran: shading then sums a bin's lights in the order forward shading does
// (the same pictures, run after run), and the shadowed lights, which the
// ShadowAtlas moved to the front, come first as shading's loops expect.
// SHORT: each invocation sorts one short list by itself (insertion), 64 bins
// a work group. LONG: one work group per long list (light_list_scan.comp
// lists them and sets this dispatch's size) sorts it together, a bitonic
// network in place with the entries past the list's end taken as greater
// than all; a group of 256 keeps each invocation's loops short enough for
// drivers that cap them (llvmpipe) up to lists of 65,536 lights.
#include "common/light_lists.glsl"
#include "common/light_list_sort.glsl"

#ifdef SHORT
layout(local_size_x = 64) in;
uniform uint u_bins;

void main() {
  uint bin = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * 64u + gl_LocalInvocationIndex;
  if (bin >= u_bins) return;
  LightRange range = u_light_ranges[bin];
  if (range.count < 2u || range.count > kShortList) return;
  for (uint i = range.offset + 1u; i < range.offset + range.count; ++i) {
    uint value = u_light_indices[i];
    uint j = i;
    for (; j > range.offset && u_light_indices[j - 1u] > value; --j) u_light_indices[j] = u_light_indices[j - 1u];
    u_light_indices[j] = value;
  }
}
#else
layout(local_size_x = 256) in;

void compare_swap(uint lo, uint hi) {
  uint a = u_light_indices[lo], b = u_light_indices[hi];
  if (a > b) {
    u_light_indices[lo] = b;
    u_light_indices[hi] = a;
  }
}

void main() {
  // Every invocation reads the same range, so the loops and barriers stay uniform.
  for (uint listed = gl_WorkGroupID.x; listed < u_long_bin_count; listed += gl_NumWorkGroups.x) {
    LightRange range = u_light_ranges[u_long_bins[listed]];
    uint size = 1u;
    while (size < range.count) size <<= 1u;
    for (uint block = 2u; block <= size; block <<= 1u) {
      for (uint half_size = block >> 1u; half_size > 0u; half_size >>= 1u) {
        for (uint pair = gl_LocalInvocationIndex; pair < size / 2u; pair += 256u) {
          uint base = (pair / half_size) * 2u * half_size, within = pair % half_size;
          uint lo = base + within;
          // The first step of each block compares mirror images (a flip), the rest neighbours half_size apart.
          uint hi = half_size == block >> 1u ? base + 2u * half_size - 1u - within : lo + half_size;
          if (hi < range.count) compare_swap(range.offset + lo, range.offset + hi);
        }
        memoryBarrierBuffer();
        barrier();
      }
    }
  }
}
#endif
