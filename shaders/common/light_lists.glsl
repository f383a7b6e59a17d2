// Per-bin light lists (a bin is a cluster or a screen tile): an (offset, count)
// range into one global array of light indices, each range in light order, and
// the lights that did not fit this frame's array, which every pixel they reach
// shades instead. C++: LightIndexList (its Total twins LightTotal).
struct LightRange {
  uint offset;
  uint count;
};

layout(std430, binding = 2) buffer LightRanges { LightRange u_light_ranges[]; };
layout(std430, binding = 3) buffer LightIndices { uint u_light_indices[]; };
layout(std430, binding = 5) buffer LightTotal {
  uint u_light_demand;         // entries every light's bins need together: the array grows to it
  uint u_light_total_wrapped;  // set when the demand passed 2^32: the C++ side refuses the frame
  uint u_light_bin_max;        // the longest list: shading loops over it
  uint u_light_capacity;       // entries u_light_indices holds (the C++ side sets it each frame)
  uint u_overflow_count;       // lights that did not fit: listed in u_overflow_lights
};
layout(std430, binding = 13) buffer OverflowLights { uint u_overflow_lights[]; };
