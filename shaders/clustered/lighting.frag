#version 450 core
// Clustered deferred lighting: reads each pixel's surface from the G-buffer,
// finds its cluster from screen position and view depth, and shades it with
// that cluster's lights only.
#include "common/frame.glsl"
#include "common/surface.glsl"
#include "common/gbuffer.glsl"
#include "common/cluster_shading.glsl"
#include "common/lighting_targets.glsl"

// With MSAA the stencil picks the pixels each rate shades (sample_rate.hpp);
// tested before the shader, rejected pixels neither run nor count as shaded.
layout(early_fragment_tests) in;

void main() {
  Surface s;
  if (!read_gbuffer(ivec2(gl_FragCoord.xy), s)) {
    write_background();
    return;
  }
  write_lighting(shade_unlit_terms(s, u_ambient.rgb), shade_cluster_lights(s, gl_FragCoord.xy));
}
