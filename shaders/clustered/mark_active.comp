#version 450 core
// --active-clusters: marks the clusters that hold at least one visible pixel,
// read from the depth buffer, so that light assignment can skip the others.
layout(local_size_x = 8, local_size_y = 8) in;

#include "common/frame.glsl"
#include "common/clusters.glsl"

layout(binding = 0) uniform sampler2D u_depth;
layout(std430, binding = 6) writeonly buffer Active { uint u_active[]; };

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, ivec2(u_viewport_size)))) return;
  float depth = texelFetch(u_depth, pixel, 0).r;
  if (depth <= kDepthFar) return;
  u_active[cluster_index(vec2(pixel) + 0.5, u_viewport_size, view_depth_from_depth(depth))] = 1u;
}
