#version 450 core
// A level of the bloom chain on the way up as a compute pass, one invocation
// per texel, stored with imageStore (the compute lighting stage; upsample.glsl).
layout(local_size_x = 8, local_size_y = 8) in;
#include "post/bloom/upsample.glsl"

// render::kPostImageUnit
layout(rgba16f, binding = 5) uniform writeonly image2D u_out;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, ivec2(u_level_size)))) return;
  imageStore(u_out, pixel, vec4(bloom_upsample(pixel), 1.0));
}
