// Per-bin light lists (a bin is a cluster or a screen tile): an (offset, count)
// range into one global array of light indices. C++: LightIndexList.
struct LightRange {
  uint offset;
  uint count;
};

layout(std430, binding = 2) buffer LightRanges { LightRange u_light_ranges[]; };
layout(std430, binding = 3) buffer LightIndices { uint u_light_indices[]; };
layout(std430, binding = 5) buffer LightTotal { uint u_light_total; };
