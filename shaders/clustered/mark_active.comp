#version 450 core
// Reads the depth buffer after the geometry (or depth pre-) pass and marks the
// cluster of every visible pixel (common/cluster_marks.glsl): its box grows to
// the pixel's view-space position, so that light assignment tests lights against
// what the cluster actually holds rather than its whole slice of the frustum.
layout(local_size_x = 8, local_size_y = 8) in;

#include "common/frame.glsl"
#include "common/clusters.glsl"
#include "common/cluster_marks.glsl"
#include "common/msaa.glsl"

layout(binding = 0) uniform target2D u_depth;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, ivec2(u_viewport_size)))) return;
  // With MSAA each sample marks its own cluster: on an edge they differ.
  for (int i = 0; i < kSamples; ++i) {
    float depth = fetch_sample(u_depth, pixel, i).r;
    if (depth <= kDepthFar) continue;
    vec2 centre = vec2(pixel) + 0.5;
    float view_depth = view_depth_from_depth(depth);
    // The pixel's view-space position, as the lighting passes see it.
    vec2 ndc = centre / u_viewport_size * 2.0 - 1.0;
    vec3 p = vec3(ndc.x * view_depth / u_projection[0][0], ndc.y * view_depth / u_projection[1][1], -view_depth);
    mark_cluster(cluster_index(centre, u_viewport_size, view_depth), p);
  }
}
