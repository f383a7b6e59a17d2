#version 450 core
// Reads the positions the shading pass will light, after the geometry (or depth
// pre-) pass, and marks the cluster of every one (common/cluster_marks.glsl):
// its box grows to the view-space position, so that light assignment tests
// lights against what the cluster actually holds rather than its whole slice of
// the frustum. Those positions are the G-buffer's (FROM_GBUFFER, deferred), or
// depths along the pixel's centre ray (forward+: the depth buffer, or with MSAA
// the pre-pass's shading depth). The depth buffer alone is not enough with
// MSAA: a pixel is shaded at its centre, and on a silhouette the centre's
// position is extrapolated off the samples the depth buffer holds.
layout(local_size_x = 8, local_size_y = 8) in;

#include "common/frame.glsl"
#include "common/clusters.glsl"
#include "common/cluster_marks.glsl"
#include "common/msaa.glsl"

#ifdef FROM_GBUFFER
#include "common/surface.glsl"
#include "common/gbuffer.glsl"
#else
layout(binding = 0) uniform target2D u_depth;

// The view-space position at `depth` on the ray through the centre of `pixel`.
vec3 centre_ray_position(ivec2 pixel, float depth) {
  vec2 ndc = (vec2(pixel) + 0.5) / u_viewport_size * 2.0 - 1.0;
  float view_depth = view_depth_from_depth(depth);
  return vec3(ndc.x * view_depth / u_projection[0][0], ndc.y * view_depth / u_projection[1][1], -view_depth);
}
#endif

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, ivec2(u_viewport_size)))) return;
  // With MSAA each sample marks its own cluster: on an edge they differ.
  for (int i = 0; i < kSamples; ++i) {
#ifdef FROM_GBUFFER
    Surface s;
    if (!read_gbuffer_sample(pixel, i, s)) continue;
    // As shade_cluster_lights computes it from the same surface.
    vec3 p = (u_view * vec4(s.position, 1.0)).xyz;
#else
    float depth = fetch_sample(u_depth, pixel, i).r;
    if (depth <= kDepthFar) continue;
    vec3 p = centre_ray_position(pixel, depth);
#endif
    mark_cluster(cluster_index(vec2(pixel) + 0.5, u_viewport_size, -p.z), p);
  }
}
