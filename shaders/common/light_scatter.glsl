// Light assignment that costs what the lights touch, not lights times bins
// (LightIndexList takes it when lights are many or small; light_gather.glsl otherwise):
// each light visits only the bins its sphere may reach (the including
// shader's for_each_bin, which calls visit_bin for every candidate bin whose
// test the light passes) in two steps around a scan (LightIndexList). A light
// with more candidates than u_big_light (a large light near the camera, a sun)
// is handed to a work group of its own, whose invocations share its
// candidates, so that a hundred large lights do not leave a hundred
// invocations walking thousands of bins each. A light's steps run in one
// program, told apart by u_step, so that they visit exactly the same bins (two
// compilations could round a test differently): large lights' in the
// LARGE_LIGHTS program (work groups that wait at barriers, which some
// drivers make every invocation of a program pay for), the others' in the plain one:
//   count        adds one to the count of each bin the light touches, then
//                reserves that many entries of the array with one atomic add
//                (the demand); a light whose entries would end past the
//                array's capacity takes its counts back and goes to the
//                overflow list instead, shaded wherever it reaches
//                (common/list_shading.glsl), so none is lost. Large lights
//                are only listed (u_big_lights) for:
//   count large  the same, one work group per listed light (counted first,
//                then added), dispatched indirectly.
//   write, write large  write each light into each bin's range at the bin's
//                cursor (light_list_scan.comp turned counts into cursors),
//                never past the bin's range; light_list_sort.comp then puts
//                each range in light order.
#include "common/light_assignment.glsl"

// Per light: where its entries went (kFitsNone, kFitsAlone, kFitsShared).
layout(std430, binding = 14) buffer LightFits { uint u_light_fits[]; };
// The large lights, and the size of the dispatch that gives each a work group.
layout(std430, binding = 12) buffer BigLights {
  uvec3 u_big_groups;  // glDispatchComputeIndirect: x at most 65,535
  uint u_big_count;
  uint u_big_lights[];
};

// Candidates past which a light gets a work group (LightIndexList::big_light_candidates):
// fewer when the lights are few, so that they still fill the GPU.
uniform uint u_big_light;
const uint kFitsNone = 0u, kFitsAlone = 1u, kFitsShared = 2u;

const uint kVisitCount = 0u, kVisitAdd = 1u, kVisitTakeBack = 2u, kVisitWrite = 3u;
uint g_visit = kVisitAdd;
uint g_light = 0u;

void visit_bin(uint bin) {
  if (g_visit == kVisitAdd) {
    atomicAdd(u_bin_counts[bin], 1u);
  } else if (g_visit == kVisitTakeBack) {
    atomicAdd(u_bin_counts[bin], 0xffffffffu);
  } else if (g_visit == kVisitWrite) {
    uint slot = atomicAdd(u_bin_counts[bin], 1u);
    LightRange range = u_light_ranges[bin];
    if (slot - range.offset < range.count) u_light_indices[slot] = g_light;
  }
}

// Defined by the including shader: how many candidate bins the light has, or
// a bound on it (it only chooses between the two paths), and a walk over the
// candidates numbered `first`, `first + stride`, ... (from 0) that calls
// visit_bin for each one the light passes and returns how many it visited.
uint candidate_count(vec4 sphere);
uint for_each_bin(vec4 sphere, uint first, uint stride);

// Reserves `bins` entries for `light`: whether they fit this frame's array.
bool reserve(uint light, uint bins) {
  if (bins == 0u) return true;
  uint first = add_demand(bins);
  bool wrapped = first > 0xffffffffu - bins;
  bool fits = !wrapped && first + bins <= u_light_capacity;
  if (!fits) u_overflow_lights[atomicAdd(u_overflow_count, 1u)] = light;
  return fits;
}

#ifdef LARGE_LIGHTS
shared uint s_visited[64];
shared bool s_fits;

// A large light's steps: each invocation of the group takes every 64th candidate.
void large_light(uint light) {
  vec4 sphere = view_sphere(light_at(light));
  uint lane = gl_LocalInvocationIndex;
  g_light = light;
  if (u_step == kStepWriteLarge) {
    if (u_light_fits[light] != kFitsShared) return;
    g_visit = kVisitWrite;
    for_each_bin(sphere, lane, 64u);
    return;
  }
  g_visit = kVisitCount;
  s_visited[lane] = for_each_bin(sphere, lane, 64u);
  barrier();
  if (lane == 0u) {
    uint bins = 0u;
    for (uint i = 0u; i < 64u; ++i) bins += s_visited[i];
    s_fits = bins > 0u && reserve(light, bins);
    u_light_fits[light] = s_fits ? kFitsShared : kFitsNone;
  }
  barrier();
  if (s_fits) {
    g_visit = kVisitAdd;
    for_each_bin(sphere, lane, 64u);
  }
  barrier();
}

void main() {
  // The loop and its barriers are uniform: every invocation of a group reads the same light.
  for (uint listed = gl_WorkGroupID.x; listed < u_big_count; listed += gl_NumWorkGroups.x) large_light(u_big_lights[listed]);
}
#else
void main() {
  uint light = gl_GlobalInvocationID.x;
  if (light >= u_light_count) return;
  vec4 sphere = view_sphere(light_at(light));
  g_light = light;
  if (u_step == kStepWrite) {
    if (u_light_fits[light] != kFitsAlone) return;
    g_visit = kVisitWrite;
    for_each_bin(sphere, 0u, 1u);
    return;
  }
  if (candidate_count(sphere) > u_big_light) {
    u_light_fits[light] = kFitsNone;
    uint listed = atomicAdd(u_big_count, 1u);
    u_big_lights[listed] = light;
    if (listed < 65535u) atomicAdd(u_big_groups.x, 1u);
    return;
  }
  g_visit = kVisitAdd;
  uint bins = for_each_bin(sphere, 0u, 1u);
  bool fits = reserve(light, bins);
  u_light_fits[light] = fits && bins > 0u ? kFitsAlone : kFitsNone;
  if (!fits) {
    // Rare (the array is sized ahead): the bins' counts must not hold it.
    g_visit = kVisitTakeBack;
    for_each_bin(sphere, 0u, 1u);
  }
}
#endif
