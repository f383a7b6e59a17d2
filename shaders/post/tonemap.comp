#version 450 core
// The tone map as a compute pass (--lighting-stage compute): reads the HDR
// colour target and stores the 8-bit display image with imageStore, one
// invocation per pixel; the same display_color() as tonemap.frag.
layout(local_size_x = 8, local_size_y = 8) in;
#include "common/frame.glsl"
#include "common/tonemap.glsl"

layout(binding = 0) uniform target2D u_hdr;
// lighting::kDisplayImageUnit
layout(rgba8, binding = 2) uniform writeonly image2D u_display;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, ivec2(u_viewport_size)))) return;
  imageStore(u_display, pixel, vec4(display_color(u_hdr, pixel), 1.0));
}
