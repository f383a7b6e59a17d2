#version 450 core
// Light volumes, base pass: what every pixel gets before any light is added:
// ambient and emission where there is geometry, the background elsewhere.
#include "common/frame.glsl"
#include "common/surface.glsl"
#include "common/gbuffer.glsl"
#include "common/shading.glsl"

layout(location = 0) out vec4 out_color;

void main() {
  Surface s;
  out_color = read_gbuffer(ivec2(gl_FragCoord.xy), s) ? vec4(shade_unlit_terms(s, u_ambient.rgb), 1.0)
                                                       : vec4(u_background.rgb, 1.0);
}
