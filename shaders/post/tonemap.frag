#version 450 core
// Final pass of every technique: reads the HDR colour target, applies exposure,
// the filmic curve and sRGB encoding, and writes the 8-bit display image.
// With MSAA it is also the resolve: each sample is tone-mapped and the results
// averaged, so a bright light's edge against a dark wall stays smooth (averaging
// HDR values first would let the bright side's value win the pixel).
#include "common/frame.glsl"
#include "common/tonemap.glsl"
#include "common/msaa.glsl"

layout(binding = 0) uniform target2D u_hdr;

in vec2 v_uv;
layout(location = 0) out vec4 out_color;

void main() {
  vec3 mapped = vec3(0.0);
  for (int i = 0; i < kSamples; ++i) mapped += tonemap_aces(fetch_sample(u_hdr, ivec2(gl_FragCoord.xy), i).rgb * u_exposure);
  out_color = vec4(linear_to_srgb(mapped / float(kSamples)), 1.0);
}
