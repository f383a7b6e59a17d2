#version 450 core
// Clustered light assignment: one invocation per cluster tests every light's
// sphere against the cluster's view-space box (lights are staged through shared
// memory in batches) and writes the indices of those that touch it into one
// global list, its range reserved with an atomic add. No per-cluster cap: when
// the list is too small the C++ side grows it and runs the pass again.
// With ACTIVE_ONLY, clusters that hold no visible pixel get no lights.
layout(local_size_x = 64) in;

#include "common/frame.glsl"
#include "common/lights.glsl"
#include "common/clusters.glsl"

struct ClusterBounds {
  vec4 lo;  // view space, xyz
  vec4 hi;
};
layout(std430, binding = 4) readonly buffer Bounds { ClusterBounds u_bounds[]; };
#ifdef ACTIVE_ONLY
layout(std430, binding = 6) readonly buffer Active { uint u_active[]; };
#endif

const uint kBatch = 256u;
shared vec4 s_lights[kBatch];  // view-space centre, radius; radius < 0: reaches everything

void load_batch(uint base) {
  for (uint i = gl_LocalInvocationIndex; i < kBatch; i += gl_WorkGroupSize.x) {
    uint l = base + i;
    if (l >= u_light_count) break;
    Light light = u_lights[l];
    bool everywhere = uint(light.color_kind.w) == kLightDirectional;
    s_lights[i] = vec4((u_view * vec4(light.position_radius.xyz, 1.0)).xyz, everywhere ? -1.0 : light.position_radius.w);
  }
}

bool touches(vec4 light, ClusterBounds box) {
  if (light.w < 0.0) return true;
  vec3 nearest = clamp(light.xyz, box.lo.xyz, box.hi.xyz) - light.xyz;
  return dot(nearest, nearest) <= light.w * light.w;
}

void main() {
  uint cluster = gl_GlobalInvocationID.x;
  bool assign = cluster < u_grid.w;
  ClusterBounds box = assign ? u_bounds[cluster] : ClusterBounds(vec4(0.0), vec4(0.0));
#ifdef ACTIVE_ONLY
  assign = assign && u_active[cluster] != 0u;
#endif
  // Count, reserve, then write: the list needs no cap per cluster.
  uint count = 0u;
  for (uint base = 0u; base < u_light_count; base += kBatch) {
    load_batch(base);
    barrier();
    uint batch = min(kBatch, u_light_count - base);
    if (assign) {
      for (uint i = 0u; i < batch; ++i) count += touches(s_lights[i], box) ? 1u : 0u;
    }
    barrier();
  }
  uint offset = count > 0u ? atomicAdd(u_light_total, count) : 0u;
  if (cluster < u_grid.w) u_light_ranges[cluster] = LightRange(offset, count);
  // The loops stay uniform across the work group: barrier() needs that.
  uint written = 0u;
  for (uint base = 0u; base < u_light_count; base += kBatch) {
    load_batch(base);
    barrier();
    uint batch = min(kBatch, u_light_count - base);
    if (assign && count > 0u) {
      for (uint i = 0u; i < batch; ++i) {
        if (touches(s_lights[i], box)) {
          uint slot = offset + written++;
          if (slot < u_list_info.x) u_light_indices[slot] = base + i;
        }
      }
    }
    barrier();
  }
}
