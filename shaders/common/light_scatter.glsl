// Light assignment that costs what the lights touch, not lights times bins:
// one invocation per light visits only the bins its sphere may reach (the
// including shader's for_each_bin, which calls visit_bin for every bin whose
// test the light passes) in two dispatches of one program around a scan
// (LightIndexList), told apart by u_step, so that both visit exactly the same
// bins (two compilations could round a test differently):
//   count step  adds one to the count of each bin the light touches, then
//               reserves that many entries of the array with one atomic add
//               (the demand); a light whose entries would end past the
//               array's capacity takes its counts back and goes to the
//               overflow list instead, shaded wherever it reaches
//               (common/list_shading.glsl), so none is lost.
//   write step  writes the light into each bin's range at the bin's cursor
//               (light_list_scan.comp turned counts into cursors), never
//               past the bin's range;
//               light_list_sort.comp then puts each range in light order.
layout(local_size_x = 64) in;

#include "common/frame.glsl"
#include "common/lights.glsl"
#include "common/light_lists.glsl"

// Per bin: the count step's count, turned by the scan into the cursor the write step advances.
layout(std430, binding = 7) buffer BinCounts { uint u_bin_counts[]; };
// Per light: 1 where its entries fit this frame's array (the count step decides, the write step reads).
layout(std430, binding = 14) buffer LightFits { uint u_light_fits[]; };

const uint kStepCount = 0u, kStepWrite = 1u;
uniform uint u_step;

const uint kVisitAdd = 0u, kVisitTakeBack = 1u, kVisitWrite = 2u;
uint g_visit = kVisitAdd;
uint g_light = 0u;

void visit_bin(uint bin) {
  if (g_visit == kVisitAdd) {
    atomicAdd(u_bin_counts[bin], 1u);
  } else if (g_visit == kVisitTakeBack) {
    atomicAdd(u_bin_counts[bin], 0xffffffffu);
  } else {
    uint slot = atomicAdd(u_bin_counts[bin], 1u);
    LightRange range = u_light_ranges[bin];
    if (slot - range.offset < range.count) u_light_indices[slot] = g_light;
  }
}

// The light's view-space centre and radius; a negative radius reaches everything.
vec4 view_sphere(Light light) {
  bool everywhere = uint(light.color_kind.w) == kLightDirectional;
  return vec4((u_view * vec4(light.position_radius.xyz, 1.0)).xyz, everywhere ? -1.0 : light.position_radius.w);
}

// Defined by the including shader: calls visit_bin(b) for every bin b the
// light reaches, in any order, and returns how many it visited.
uint for_each_bin(vec4 sphere);

void main() {
  uint light = gl_GlobalInvocationID.x;
  if (light >= u_light_count) return;
  vec4 sphere = view_sphere(u_lights[light]);
  g_light = light;
  if (u_step == kStepWrite) {
    if (u_light_fits[light] == 0u) return;
    g_visit = kVisitWrite;
    for_each_bin(sphere);
    return;
  }
  g_visit = kVisitAdd;
  uint bins = for_each_bin(sphere);
  bool fits = true;
  if (bins > 0u) {
    uint first = atomicAdd(u_light_demand, bins);
    bool wrapped = first > 0xffffffffu - bins;
    if (wrapped) u_light_total_wrapped = 1u;
    fits = !wrapped && first + bins <= u_light_capacity;
  }
  u_light_fits[light] = fits && bins > 0u ? 1u : 0u;
  if (!fits) {
    // Rare (the array is sized ahead): the bins' counts must not hold it.
    g_visit = kVisitTakeBack;
    for_each_bin(sphere);
    u_overflow_lights[atomicAdd(u_overflow_count, 1u)] = light;
  }
}
