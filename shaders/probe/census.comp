#version 450 core
// Stage probe, compute side: one invocation per pixel in 8x8 groups runs the
// probe's arithmetic and stores it (gfx/stage_probe.hpp), so its time and the
// SMs it reaches compare with the fragment side's over the same pixels.
#include "probe/census.glsl"
layout(local_size_x = 8, local_size_y = 8) in;

layout(r32f, binding = 0) uniform writeonly image2D u_out;

void main() {
  const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, imageSize(u_out)))) return;
  count_invocation();
  imageStore(u_out, pixel, vec4(arithmetic(vec2(pixel) * 1e-3)));
}
