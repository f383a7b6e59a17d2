#version 450 core
// Reads the depth buffer after the geometry (or depth pre-) pass. Default
// (--cluster-bounds pixels): writes each cluster's view-space box of the pixels
// it holds (least and greatest x, y, z as ordered integers; untouched clusters
// stay empty), so that light assignment tests lights against what the cluster
// actually holds rather than its whole slice of the frustum. With
// ACTIVE_FLAGS (--cluster-bounds grid --active-clusters): only marks the
// clusters that hold a visible pixel.
layout(local_size_x = 8, local_size_y = 8) in;

#include "common/frame.glsl"
#include "common/clusters.glsl"

layout(binding = 0) uniform sampler2D u_depth;
#ifdef ACTIVE_FLAGS
layout(std430, binding = 6) writeonly buffer Active { uint u_active[]; };
#else
// [0, clusters): least xyz; [clusters, 2 * clusters): greatest xyz.
layout(std430, binding = 6) buffer PixelBounds { uvec4 u_pixel_bounds[]; };
#endif

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, ivec2(u_viewport_size)))) return;
  float depth = texelFetch(u_depth, pixel, 0).r;
  if (depth <= kDepthFar) return;
  vec2 centre = vec2(pixel) + 0.5;
  float view_depth = view_depth_from_depth(depth);
  uint cluster = cluster_index(centre, u_viewport_size, view_depth);
#ifdef ACTIVE_FLAGS
  u_active[cluster] = 1u;
#else
  // The pixel's view-space position, as the lighting passes see it.
  vec2 ndc = centre / u_viewport_size * 2.0 - 1.0;
  vec3 p = vec3(ndc.x * view_depth / u_projection[0][0], ndc.y * view_depth / u_projection[1][1], -view_depth);
  uvec3 ordered = uvec3(float_to_ordered(p.x), float_to_ordered(p.y), float_to_ordered(p.z));
  atomicMin(u_pixel_bounds[cluster].x, ordered.x);
  atomicMin(u_pixel_bounds[cluster].y, ordered.y);
  atomicMin(u_pixel_bounds[cluster].z, ordered.z);
  atomicMax(u_pixel_bounds[u_grid.w + cluster].x, ordered.x);
  atomicMax(u_pixel_bounds[u_grid.w + cluster].y, ordered.y);
  atomicMax(u_pixel_bounds[u_grid.w + cluster].z, ordered.z);
#endif
}
