#version 450 core
// The bloomed image as a compute pass, one invocation per pixel stored with
// imageStore (the compute lighting stage, which has no MSAA; composite.glsl).
layout(local_size_x = 8, local_size_y = 8) in;
#include "post/bloom/composite.glsl"

// render::kPostImageUnit
layout(rgba16f, binding = 5) uniform writeonly image2D u_out;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, ivec2(u_size)))) return;
  imageStore(u_out, pixel, bloom_composite(pixel, 0, bloom_glow(pixel)));
}
