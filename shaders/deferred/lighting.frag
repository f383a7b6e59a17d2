#version 450 core
// Deferred lighting: one full-screen pass that reads each pixel's surface from
// the G-buffer and loops over every light. With LIGHT_RADIUS_CULL (mode
// deferred-radius) a light whose radius does not reach the pixel is skipped;
// the falloff is already zero there, so the picture does not change.
#include "common/frame.glsl"
#include "common/surface.glsl"
#include "common/gbuffer.glsl"
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
  vec3 v = normalize(u_camera_position.xyz - s.position);
  LightSum sum = no_light();
  add_buffer_lights(sum, s, v);
  write_lighting(shade_unlit_terms(s, u_ambient.rgb), sum);
}
