// Per-bin light lists (a bin is a cluster or a screen tile): an (offset, count)
// range into one global array of light indices. C++: LightIndexList.
struct LightRange {
  uint offset;
  uint count;
};

layout(std430, binding = 2) buffer LightRanges { LightRange u_light_ranges[]; };
layout(std430, binding = 3) buffer LightIndices { uint u_light_indices[]; };
layout(std430, binding = 5) buffer LightTotal {
  uint u_light_total;
  uint u_light_total_wrapped;  // set when the total passed 2^32: the C++ side refuses the frame
  uint u_light_bin_max;        // the longest list: shading loops over it
};

// Reserves `count` consecutive entries of the global list; returns the first.
uint reserve_light_range(uint count) {
  if (count == 0u) return 0u;
  atomicMax(u_light_bin_max, count);
  uint offset = atomicAdd(u_light_total, count);
  if (offset > 0xffffffffu - count) u_light_total_wrapped = 1u;
  return offset;
}
