// Per-bin light lists (a bin is a cluster or a screen tile): an (offset, count)
// range into one global array of light indices, each range in light order, and
// the lights that did not fit this frame's array, which every pixel they reach
// shades instead. C++: LightIndexList (its Total twins LightTotal).
struct LightRange {
  uint offset;
  uint count;
};

#ifdef NO_STORAGE_BUFFERS
// The compute-free tier: lists built on the CPU (render/lighting/cpu_light_lists.hpp)
// in integer textures of kListTextureWidth texels a row, per bin its range
// (RG32UI: offset, count), then the indices (R32UI). They always fit: no
// light overflows. C++ twin: ListTextures in src/render/storage_free.hpp.
const uint kListTextureWidth = 2048u;
layout(binding = 8) uniform highp usampler2D u_light_range_texture;
layout(binding = 9) uniform highp usampler2D u_light_index_texture;

ivec2 list_texel(uint i) { return ivec2(i % kListTextureWidth, i / kListTextureWidth); }
LightRange light_range(uint bin) {
  uvec2 range = texelFetch(u_light_range_texture, list_texel(bin), 0).xy;
  return LightRange(range.x, range.y);
}
uint light_index(uint entry) { return texelFetch(u_light_index_texture, list_texel(entry), 0).x; }
uint overflow_count() { return 0u; }
uint overflow_light(uint o) { return 0u; }
#else
layout(std430, binding = 2) buffer LightRanges { LightRange u_light_ranges[]; };
layout(std430, binding = 3) buffer LightIndices { uint u_light_indices[]; };
layout(std430, binding = 5) buffer LightTotal {
  uint u_light_demand;         // entries every light's bins need together: the array grows to it
  uint u_light_total_wrapped;  // set when the demand passed 2^32: the C++ side refuses the frame
  uint u_light_bin_max;        // the longest list: shading loops over it
  uint u_light_capacity;       // entries u_light_indices holds (the C++ side sets it each frame)
  uint u_overflow_count;       // lights that did not fit: listed in u_overflow_lights
  uint u_light_filled_bins;    // bins holding a light (LightIndexList's choice of assignment)
};
layout(std430, binding = 13) buffer OverflowLights { uint u_overflow_lights[]; };

LightRange light_range(uint bin) { return u_light_ranges[bin]; }
uint light_index(uint entry) { return u_light_indices[entry]; }
uint overflow_count() { return u_overflow_count; }
uint overflow_light(uint o) { return u_overflow_lights[o]; }
#endif
