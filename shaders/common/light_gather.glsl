// Light assignment bin by bin (LightIndexList takes it when few lights each
// reach much of the screen, as large lights near the camera do; docs/techniques.md):
// each invocation owns one bin and tests every light against it, so a bin's
// list needs no atomics and comes out in light order (no sort), for a cost of
// bins times lights instead of the scatter's atomics per hit. A work group's 64
// bins, a block of 8x8 tiles (of one depth slice, for clusters) so that their
// box stays small, stage the lights through shared memory, 1,024 at a time, each
// invocation keeping in a segment of its own those that touch the box around
// the group's bins (a light far from them costs one test for the group, not
// 64); the segments are read in order, which keeps light order. Steps (u_step):
//   count     each bin's count, added to the demand; the scan makes the ranges.
//   write     each bin writes its range, when the demand fits this frame's
//             array; when it does not, the ranges are emptied and
//   overflow  (one invocation per light) lists every light, shaded wherever it
//             reaches (common/list_shading.glsl): none is lost, the frame is
//             slower, and the array grows for the next.
// The bins are numbered (slice * u_bin_shape.y + row) * u_bin_shape.x + column
// (tiles: one slice); the including shader defines what each holds:
uniform uvec3 u_bin_shape;
// Loads `bin` for gather_touches and gives a view-space box holding what it
// holds; false when the bin gets no lights.
bool gather_bin(uint bin, out vec3 lo, out vec3 hi);
// The loaded bin's test: the one its scatter's walk applies.
bool gather_touches(vec4 sphere);

#include "common/light_assignment.glsl"

const uint kPerInvocation = 16u;
const uint kBatch = 64u * kPerInvocation;
shared vec4 s_spheres[kBatch];
shared uint s_ids[kBatch];
shared uint s_kept[64];
shared vec3 s_lo[64], s_hi[64];
shared vec3 s_group_lo, s_group_hi;

bool touches_box(vec4 sphere, vec3 lo, vec3 hi) {
  if (sphere.w < 0.0) return true;
  vec3 nearest = clamp(sphere.xyz, lo, hi) - sphere.xyz;
  return dot(nearest, nearest) <= sphere.w * sphere.w;
}

bool demand_fits() { return u_light_total_wrapped == 0u && u_light_demand <= u_light_capacity; }

void list_every_light() {
  uint light = gl_GlobalInvocationID.x;
  if (demand_fits() || light >= u_light_count) return;
  u_overflow_lights[light] = light;
  if (light == 0u) u_overflow_count = u_light_count;
}

// Stages the lights [base, base + kBatch) that touch the group's box.
void stage(uint base) {
  uint lane = gl_LocalInvocationIndex, segment = lane * kPerInvocation, kept = 0u;
  for (uint k = 0u; k < kPerInvocation; ++k) {
    uint light = base + segment + k;
    if (light >= u_light_count) break;
    vec4 sphere = view_sphere(light_at(light));
    if (!touches_box(sphere, s_group_lo, s_group_hi)) continue;
    s_spheres[segment + kept] = sphere;
    s_ids[segment + kept] = light;
    ++kept;
  }
  s_kept[lane] = kept;
}

// This invocation's bin in its group's 8x8 block; false past the grid's edge.
bool block_bin(out uint bin) {
  uvec2 blocks = (u_bin_shape.xy + 7u) / 8u;
  uint group = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
  uint slice = group / (blocks.x * blocks.y), block = group % (blocks.x * blocks.y);
  uvec2 cell = uvec2(block % blocks.x, block / blocks.x) * 8u + uvec2(gl_LocalInvocationIndex % 8u, gl_LocalInvocationIndex / 8u);
  bin = (slice * u_bin_shape.y + cell.y) * u_bin_shape.x + cell.x;
  return all(lessThan(cell, u_bin_shape.xy)) && slice < u_bin_shape.z;
}

void main() {
  if (u_step == kStepOverflow) {
    list_every_light();
    return;
  }
  uint lane = gl_LocalInvocationIndex, bin;
  vec3 lo, hi;
  bool live = block_bin(bin) && gather_bin(bin, lo, hi);
  s_lo[lane] = live ? lo : vec3(1e30);
  s_hi[lane] = live ? hi : vec3(-1e30);
  barrier();
  if (lane == 0u) {
    vec3 group_lo = vec3(1e30), group_hi = vec3(-1e30);
    for (uint i = 0u; i < 64u; ++i) {
      group_lo = min(group_lo, s_lo[i]);
      group_hi = max(group_hi, s_hi[i]);
    }
    s_group_lo = group_lo;
    s_group_hi = group_hi;
  }
  barrier();
  // Both are the same for the whole group: the loop's barriers stay uniform.
  if (any(greaterThan(s_group_lo, s_group_hi))) return;
  bool write = u_step == kStepWrite;
  if (write && !demand_fits()) {
    if (live) u_light_ranges[bin] = LightRange(0u, 0u);
    return;
  }
  uint count = 0u, next = write && live ? u_light_ranges[bin].offset : 0u;
  for (uint base = 0u; base < u_light_count; base += kBatch) {
    stage(base);
    barrier();
    for (uint segment = 0u; live && segment < 64u; ++segment) {
      for (uint i = segment * kPerInvocation, stop = i + s_kept[segment]; i < stop; ++i) {
        if (!gather_touches(s_spheres[i])) continue;
        if (write) u_light_indices[next++] = s_ids[i];
        else ++count;
      }
    }
    barrier();
  }
  if (!write && live) {
    u_bin_counts[bin] = count;
    add_demand(count);
  }
}
