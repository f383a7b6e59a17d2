#version 450 core
// Clustered light assignment in three dispatches over (cluster, light chunk)
// pairs: COUNT tests a chunk of lights against a cluster's view-space box and
// stores how many touch it; RESERVE (one invocation per cluster) turns the
// chunks' counts into offsets and reserves the cluster's range of the global
// list with one atomic add; WRITE tests again and writes the indices. Chunking
// bounds the loop any one invocation runs (llvmpipe ends a shader's loops after
// 65,535 iterations in all) and spreads a million lights over many invocations.
// No cap per cluster: when the list is too small the C++ side grows it and runs
// the three steps again. With PIXEL_BOUNDS (the default) each cluster is tested
// by the box of the pixels it holds (mark_active.comp), padded by a millimetre
// per metre for the lighting passes' own reconstruction of those positions;
// clusters without pixels get no lights. With ACTIVE_ONLY, the grid's boxes,
// and clusters that hold no visible pixel get no lights.
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
#ifdef PIXEL_BOUNDS
layout(std430, binding = 6) readonly buffer PixelBounds { uvec4 u_pixel_bounds[]; };

// The box of the cluster's pixels; false when it holds none.
bool pixel_box(uint cluster, out ClusterBounds box) {
  uvec4 lo = u_pixel_bounds[cluster], hi = u_pixel_bounds[u_grid.w + cluster];
  if (lo.x > hi.x) return false;
  vec3 l = vec3(ordered_to_float(lo.x), ordered_to_float(lo.y), ordered_to_float(lo.z));
  vec3 h = vec3(ordered_to_float(hi.x), ordered_to_float(hi.y), ordered_to_float(hi.z));
  vec3 pad = vec3(1e-3 * (1.0 + max(-l.z, 0.0)));
  box = ClusterBounds(vec4(l - pad, 0.0), vec4(h + pad, 0.0));
  return true;
}
#endif
// Per chunk and cluster (chunk-major): COUNT writes the count, RESERVE
// replaces it with the chunk's offset within the cluster's range.
layout(std430, binding = 7) buffer ChunkCounts { uint u_chunk_counts[]; };

uint chunk_count() { return (u_light_count + LIGHT_CHUNK - 1u) / LIGHT_CHUNK; }

#ifdef STEP_RESERVE
void main() {
  uint cluster = gl_GlobalInvocationID.x;
  if (cluster >= u_grid.w) return;
  uint total = 0u;
  for (uint chunk = 0u; chunk < chunk_count(); ++chunk) {
    uint slot = chunk * u_grid.w + cluster;
    uint count = u_chunk_counts[slot];
    u_chunk_counts[slot] = total;
    total += count;
  }
  u_light_ranges[cluster] = LightRange(reserve_light_range(total), total);
}
#else
// Lights are staged through shared memory in batches of 1024, sixteen per
// invocation. Each invocation keeps, in its own segment, only those that touch
// the box around the work group's 64 clusters, so a small light far from these
// clusters costs one test per work group, not 64; reading the segments in
// order keeps the lists in light order (the same sums, the same pixels).
const uint kPerInvocation = 16u;
const uint kBatch = 64u * kPerInvocation;
shared vec4 s_lights[kBatch];  // view-space centre, radius; radius < 0: reaches everything
shared uint s_ids[kBatch];
shared uint s_kept[64];
shared ClusterBounds s_group;

bool touches(vec4 light, ClusterBounds box);

void load_group_bounds() {
  if (gl_LocalInvocationIndex == 0u) {
    uint first = gl_WorkGroupID.x * 64u, last = min(first + 64u, u_grid.w);
    ClusterBounds group = ClusterBounds(vec4(1e30), vec4(-1e30));
    for (uint c = first; c < last; ++c) {
      group.lo = min(group.lo, u_bounds[c].lo);
      group.hi = max(group.hi, u_bounds[c].hi);
    }
    s_group = group;
  }
  barrier();
}

// Fills each invocation's segment of s_lights with the lights of [base, end) that reach the group.
void load_batch(uint base, uint end) {
  uint local = gl_LocalInvocationIndex, segment = local * kPerInvocation, kept = 0u;
  for (uint k = 0u; k < kPerInvocation; ++k) {
    uint l = base + segment + k;
    if (l >= end) break;
    Light light = u_lights[l];
    bool everywhere = uint(light.color_kind.w) == kLightDirectional;
    vec4 sphere = vec4((u_view * vec4(light.position_radius.xyz, 1.0)).xyz, everywhere ? -1.0 : light.position_radius.w);
    if (touches(sphere, s_group)) {
      s_lights[segment + kept] = sphere;
      s_ids[segment + kept] = l;
      ++kept;
    }
  }
  s_kept[local] = kept;
  barrier();
}

bool touches(vec4 light, ClusterBounds box) {
  if (light.w < 0.0) return true;
  vec3 nearest = clamp(light.xyz, box.lo.xyz, box.hi.xyz) - light.xyz;
  return dot(nearest, nearest) <= light.w * light.w;
}

void main() {
  uint cluster = gl_GlobalInvocationID.x;
  uint chunk = gl_WorkGroupID.y;
  bool assign = cluster < u_grid.w;
  ClusterBounds box = assign ? u_bounds[cluster] : ClusterBounds(vec4(0.0), vec4(0.0));
#ifdef ACTIVE_ONLY
  assign = assign && u_active[cluster] != 0u;
#endif
#ifdef PIXEL_BOUNDS
  assign = assign && pixel_box(cluster, box);
#endif
  uint first = chunk * LIGHT_CHUNK, end = min(first + LIGHT_CHUNK, u_light_count);
  uint slot = chunk * u_grid.w + cluster;
#ifdef STEP_WRITE
  uint next = 0u, last = 0u;
  if (assign) {
    LightRange range = u_light_ranges[cluster];
    next = range.offset + u_chunk_counts[slot];
    last = range.offset + range.count;
  }
#else
  uint count = 0u;
#endif
  // The loop stays uniform across the work group: barrier() needs that.
  load_group_bounds();
  for (uint base = first; base < end; base += kBatch) {
    load_batch(base, end);
    if (assign) {
      for (uint segment = 0u; segment < 64u; ++segment) {
        for (uint i = segment * kPerInvocation, stop = i + s_kept[segment]; i < stop; ++i) {
          if (!touches(s_lights[i], box)) continue;
#ifdef STEP_WRITE
          if (next < last && next < u_list_info.x) u_light_indices[next] = s_ids[i];
          ++next;
#else
          ++count;
#endif
        }
      }
    }
    barrier();
  }
#ifndef STEP_WRITE
  if (cluster < u_grid.w) u_chunk_counts[slot] = count;
#endif
}
#endif
