#version 450 core
// Light volumes, base pass: what every pixel gets before any light is added:
// ambient and emission where there is geometry, the background elsewhere.
#include "common/frame.glsl"
#include "common/surface.glsl"
#include "common/gbuffer.glsl"
#include "common/lighting_targets.glsl"

// With MSAA the stencil picks the pixels each rate shades (sample_rate.hpp);
// tested before the shader, rejected pixels neither run nor count as shaded.
layout(early_fragment_tests) in;

void main() {
  Surface s;
  if (read_gbuffer(ivec2(gl_FragCoord.xy), s)) write_lighting(shade_unlit_terms(s, u_ambient.rgb), no_light());
  else write_background();
}
