#version 450 core
// Tiled light culling, first step: one work group per 16x16-pixel tile reads
// the tile's depths and writes its frustum (four side planes through the eye)
// and the view-depth bounds of what it holds, which tiled/assign.comp tests
// each light against. With BLENDED the bounds are those of blended surfaces: a
// pixel's run from the nearest blended surface in front of its opaque one
// (u_blended_depth) back to that opaque one. With MSAA they take in every
// sample. The opaque bounds come from the G-buffer's positions, the very
// points the lighting pass shades: with MSAA a silhouette pixel's stored
// position is extrapolated to its centre, off the depths the depth buffer
// holds for its samples.
layout(local_size_x = 16, local_size_y = 16) in;

#include "common/frame.glsl"
#include "common/msaa.glsl"
#include "tiled/tiles.glsl"

#ifdef BLENDED
layout(binding = 0) uniform target2D u_depth;
// The opaque depth with the blended surfaces drawn over it.
layout(binding = 1) uniform target2D u_blended_depth;
#else
#include "common/surface.glsl"
#include "common/gbuffer.glsl"
#endif

shared uint s_min_depth;  // float bits: positive floats order like their bits
shared uint s_max_depth;

// The view-space direction of the ray through a pixel corner (at depth 1).
vec3 corner_ray(vec2 pixel) {
  vec2 ndc = pixel / u_viewport_size * 2.0 - 1.0;
  vec4 point = inverse(u_projection) * vec4(ndc, kDepthNear, 1.0);
  vec3 on_near = point.xyz / point.w;
  return on_near / -on_near.z;
}

void main() {
  uvec2 tile = gl_WorkGroupID.xy;
  if (gl_LocalInvocationIndex == 0u) {
    s_min_depth = floatBitsToUint(1e30);
    s_max_depth = 0u;
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
  if (gl_LocalInvocationIndex != 0u) return;
  // Side planes through the eye and the tile's corner rays, normals inward.
  vec2 lo = vec2(tile * 16u), hi = min(lo + 16.0, u_viewport_size);
  vec3 a = corner_ray(lo), b = corner_ray(vec2(hi.x, lo.y)), c = corner_ray(hi), d = corner_ray(vec2(lo.x, hi.y));
  TileBounds bounds;
  bounds.planes[0] = vec4(normalize(cross(b, a)), 0.0);
  bounds.planes[1] = vec4(normalize(cross(c, b)), 0.0);
  bounds.planes[2] = vec4(normalize(cross(d, c)), 0.0);
  bounds.planes[3] = vec4(normalize(cross(a, d)), 0.0);
  bool empty = s_max_depth == 0u;
  bounds.depths = vec4(uintBitsToFloat(s_min_depth), uintBitsToFloat(s_max_depth), empty ? 1.0 : 0.0, 0.0);
  u_tile_bounds[tile.y * u_tiles.x + tile.x] = bounds;
}
