#version 450 core
// A level of the bloom chain as a compute pass, one invocation per texel,
// stored with imageStore (the compute lighting stage; downsample.glsl).
layout(local_size_x = 8, local_size_y = 8) in;
#include "post/bloom/downsample.glsl"

// render::kPostImageUnit
layout(rgba16f, binding = 5) uniform writeonly image2D u_out;
uniform vec2 u_out_size;

void main() {
  ivec2 o = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(o, ivec2(u_out_size)))) return;
  imageStore(u_out, o, vec4(bloom_downsample(o), 1.0));
}
