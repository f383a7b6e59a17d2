// What both light assignments share: LightIndexList runs light_scatter.glsl
// (each light visits the bins it may reach) or light_gather.glsl (each bin
// tests every light), chosen per frame (LightAssignment); the including
// shader (tiled/assign.comp, clustered/assign.comp) gives the bins and the
// test, the same for both, so both write the same lists.
layout(local_size_x = 64) in;

#include "common/frame.glsl"
#include "common/lights.glsl"
#include "common/light_lists.glsl"

// Per bin: the count step's count, turned by the scan into the cursor a scatter's write step advances.
layout(std430, binding = 7) buffer BinCounts { uint u_bin_counts[]; };

// The steps (u_step; LightIndexList names them the same).
const uint kStepCount = 0u, kStepCountLarge = 1u, kStepWrite = 2u, kStepWriteLarge = 3u, kStepOverflow = 4u;
uniform uint u_step;

// The light's view-space centre and radius; a negative radius reaches everything.
vec4 view_sphere(Light light) {
  bool everywhere = uint(light.color_kind.w) == kLightDirectional;
  return vec4((u_view * vec4(light.position_radius.xyz, 1.0)).xyz, everywhere ? -1.0 : light.position_radius.w);
}

// Adds a count step's entries to the demand, flagging a demand past 2^32; returns where they start.
uint add_demand(uint entries) {
  uint first = atomicAdd(u_light_demand, entries);
  if (first > 0xffffffffu - entries) u_light_total_wrapped = 1u;
  return first;
}
