#version 450 core
// Reads the depth buffer after the first geometry pass (every sample with
// MSAA); writes the farthest view depth of each 8x8-pixel tile (infinity where
// some sample holds no geometry): the finest level of occlusion culling's depth
// pyramid, read back for the CPU or reduced further on the GPU
// (depth_pyramid.comp; src/render/culling/): whatever lies behind it is hidden.
layout(local_size_x = 8, local_size_y = 8) in;

#include "common/frame.glsl"
#include "common/msaa.glsl"

layout(binding = 14) uniform target2D u_depth;
layout(std430, binding = 10) writeonly buffer TileDepths { float u_farthest[]; };

shared float s_farthest[64];

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  // Reversed Z: the farthest sample has the smallest depth. Pixels past the
  // viewport's edge hide nothing and are left out (the near plane's depth).
  float farthest = kDepthNear;
  if (all(lessThan(pixel, ivec2(u_viewport_size)))) {
    for (int i = 0; i < kSamples; ++i) farthest = min(farthest, fetch_sample(u_depth, pixel, i).r);
  }
  s_farthest[gl_LocalInvocationIndex] = farthest;
  barrier();
  for (uint stride = 32u; stride > 0u; stride >>= 1) {
    if (gl_LocalInvocationIndex < stride) {
      s_farthest[gl_LocalInvocationIndex] = min(s_farthest[gl_LocalInvocationIndex], s_farthest[gl_LocalInvocationIndex + stride]);
    }
    barrier();
  }
  if (gl_LocalInvocationIndex == 0u) {
    float depth = s_farthest[0];
    u_farthest[gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x] =
        depth <= kDepthFar ? uintBitsToFloat(0x7f800000u) : view_depth_from_depth(depth);
  }
}
