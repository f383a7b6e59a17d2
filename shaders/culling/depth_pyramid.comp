#version 450 core
// Reads one level of the depth pyramid (farthest view depth per texel) and
// writes the next coarser one, each texel the farthest of the 2x2 below it:
// the GPU twin of DepthPyramid's constructor (src/render/culling/occlusion_culling.cpp),
// so that occlusion_cull.comp tests boxes without the depth leaving the GPU.
layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, binding = 10) buffer Pyramid { float u_pyramid[]; };

uniform ivec4 u_source;  // xy: size in texels, z: offset of its first texel
uniform ivec4 u_target;

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, u_target.xy))) return;
  float farthest = 0.0;
  for (int dy = 0; dy < 2; ++dy) {
    for (int dx = 0; dx < 2; ++dx) {
      ivec2 below = min(2 * texel + ivec2(dx, dy), u_source.xy - 1);
      farthest = max(farthest, u_pyramid[u_source.z + below.y * u_source.x + below.x]);
    }
  }
  u_pyramid[u_target.z + texel.y * u_target.x + texel.x] = farthest;
}
