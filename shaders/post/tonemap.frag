#version 450 core
// Final pass of every technique: reads the HDR colour target, applies exposure,
// the filmic curve and sRGB encoding, and writes the 8-bit display image.
#include "common/frame.glsl"
#include "common/tonemap.glsl"

layout(binding = 0) uniform sampler2D u_hdr;

in vec2 v_uv;
layout(location = 0) out vec4 out_color;

void main() {
  vec3 hdr = texelFetch(u_hdr, ivec2(gl_FragCoord.xy), 0).rgb;
  out_color = vec4(linear_to_srgb(tonemap_aces(hdr * u_exposure)), 1.0);
}
