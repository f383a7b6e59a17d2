#version 450 core
// Tiled light culling: one work group per 16x16-pixel tile reads the tile's
// depths, takes their view-space bounds, and tests every light's sphere against
// the tile's frustum (four side planes and the depth bounds). Matching lights
// are counted, a range of the global list is reserved with one atomic add per
// tile, and the indices written, those with shadow maps first: no cap per
// tile. With BLENDED it fills the list for blended surfaces instead: a
// pixel's bounds run from the nearest blended surface in front of its opaque
// one (u_blended_depth) back to that opaque one. With MSAA the bounds take in
// every sample. The opaque bounds are read from the G-buffer's positions, the
// very points the lighting pass shades: with MSAA a silhouette pixel's stored
// position is extrapolated to its centre, off the depths the depth buffer
// holds for its samples.
layout(local_size_x = 16, local_size_y = 16) in;

#include "common/frame.glsl"
#include "common/lights.glsl"
#include "common/shadows.glsl"
#include "common/light_lists.glsl"
#include "common/msaa.glsl"

#ifdef BLENDED
layout(binding = 0) uniform target2D u_depth;
// The opaque depth with the blended surfaces drawn over it.
layout(binding = 1) uniform target2D u_blended_depth;
#else
#include "common/surface.glsl"
#include "common/gbuffer.glsl"
#endif
uniform uvec2 u_tiles;
uniform uint u_list_capacity;

shared uint s_min_depth;  // float bits: positive floats order like their bits
shared uint s_max_depth;
shared uint s_count;
shared uint s_shadowed;  // of s_count, the lights with shadow maps: written first
shared uint s_offset;
shared uint s_written;
shared uint s_written_shadowed;
shared vec4 s_planes[4];

// The view-space direction of the ray through a pixel corner (at depth 1).
vec3 corner_ray(vec2 pixel) {
  vec2 ndc = pixel / u_viewport_size * 2.0 - 1.0;
  vec4 point = inverse(u_projection) * vec4(ndc, kDepthNear, 1.0);
  vec3 on_near = point.xyz / point.w;
  return on_near / -on_near.z;
}

bool touches(Light light, float near_depth, float far_depth) {
  if (uint(light.color_kind.w) == kLightDirectional) return true;
  vec3 centre = (u_view * vec4(light.position_radius.xyz, 1.0)).xyz;
  float radius = light.position_radius.w;
  if (-centre.z + radius < near_depth || -centre.z - radius > far_depth) return false;
  for (int p = 0; p < 4; ++p) {
    if (dot(s_planes[p].xyz, centre) < -radius) return false;
  }
  return true;
}

void main() {
  uvec2 tile = gl_WorkGroupID.xy;
  uint tile_index = tile.y * u_tiles.x + tile.x;
  if (gl_LocalInvocationIndex == 0u) {
    s_min_depth = floatBitsToUint(1e30);
    s_max_depth = 0u;
    s_count = 0u;
    s_shadowed = 0u;
    s_written = 0u;
    s_written_shadowed = 0u;
    // Side planes through the eye and the tile's corner rays, normals inward.
    vec2 lo = vec2(tile * 16u), hi = min(lo + 16.0, u_viewport_size);
    vec3 a = corner_ray(lo), b = corner_ray(vec2(hi.x, lo.y)), c = corner_ray(hi), d = corner_ray(vec2(lo.x, hi.y));
    s_planes[0] = vec4(normalize(cross(b, a)), 0.0);
    s_planes[1] = vec4(normalize(cross(c, b)), 0.0);
    s_planes[2] = vec4(normalize(cross(d, c)), 0.0);
    s_planes[3] = vec4(normalize(cross(a, d)), 0.0);
  }
  barrier();
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  for (int i = 0; i < kSamples && all(lessThan(pixel, ivec2(u_viewport_size))); ++i) {
#ifdef BLENDED
    float depth = fetch_sample(u_depth, pixel, i).r;
    float front = fetch_sample(u_blended_depth, pixel, i).r;
    if (front > depth) {
      // Glass over the sky reaches to the far plane.
      atomicMin(s_min_depth, floatBitsToUint(view_depth_from_depth(front)));
      atomicMax(s_max_depth, floatBitsToUint(depth > kDepthFar ? view_depth_from_depth(depth) : u_far));
    }
#else
    Surface s;
    if (read_gbuffer_sample(pixel, i, s)) {
      float view_depth = max(-(u_view * vec4(s.position, 1.0)).z, 0.0);  // ordered as bits: not negative
      atomicMin(s_min_depth, floatBitsToUint(view_depth));
      atomicMax(s_max_depth, floatBitsToUint(view_depth));
    }
#endif
  }
  barrier();
  float near_depth = uintBitsToFloat(s_min_depth), far_depth = uintBitsToFloat(s_max_depth);
  bool empty = s_max_depth == 0u;
  uint threads = gl_WorkGroupSize.x * gl_WorkGroupSize.y;
  if (!empty) {
    for (uint l = gl_LocalInvocationIndex; l < u_light_count; l += threads) {
      if (touches(u_lights[l], near_depth, far_depth)) {
        atomicAdd(s_count, 1u);
        if (has_shadow_maps(u_lights[l])) atomicAdd(s_shadowed, 1u);
      }
    }
  }
  barrier();
  if (gl_LocalInvocationIndex == 0u) {
    s_offset = reserve_light_range(s_count);
    u_light_ranges[tile_index] = LightRange(s_offset, s_count);
  }
  barrier();
  if (!empty) {
    for (uint l = gl_LocalInvocationIndex; l < u_light_count; l += threads) {
      if (touches(u_lights[l], near_depth, far_depth)) {
        // Shadowed lights first, as shading loops take them (common/list_shading.glsl).
        uint slot = s_offset + (has_shadow_maps(u_lights[l]) ? atomicAdd(s_written_shadowed, 1u) : s_shadowed + atomicAdd(s_written, 1u));
        if (slot < u_list_capacity) u_light_indices[slot] = l;
      }
    }
  }
}
