#version 450 core
// Final pass of every technique: reads the HDR colour target, applies exposure,
// the filmic curve and sRGB encoding, and writes the 8-bit display image. With
// MSAA it is also the resolve (display_color in common/tonemap.glsl).
#include "common/frame.glsl"
#include "common/tonemap.glsl"

layout(binding = 0) uniform target2D u_hdr;

in vec2 v_uv;
layout(location = 0) out vec4 out_color;

void main() { out_color = vec4(display_color(u_hdr, ivec2(gl_FragCoord.xy)), 1.0); }
