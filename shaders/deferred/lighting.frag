#version 450 core
// Deferred lighting: one full-screen pass that reads each pixel's surface from
// the G-buffer and loops over every light. With LIGHT_RADIUS_CULL (mode
// deferred-radius) a light whose radius does not reach the pixel is skipped;
// the falloff is already zero there, so the picture does not change.
#include "common/frame.glsl"
#include "common/surface.glsl"
#include "common/gbuffer.glsl"
#include "common/shading.glsl"

layout(location = 0) out vec4 out_color;

void main() {
  Surface s;
  if (!read_gbuffer(ivec2(gl_FragCoord.xy), s)) {
    out_color = vec4(u_background.rgb, 1.0);
    return;
  }
  vec3 v = normalize(u_camera_position.xyz - s.position);
  vec3 color = shade_unlit_terms(s, u_ambient.rgb);
  for (uint i = 0u; i < u_light_count; ++i) {
#ifdef LIGHT_RADIUS_CULL
    if (!light_reaches(u_lights[i], s.position)) continue;
#endif
    color += shade_light(s, v, u_lights[i]);
  }
  out_color = vec4(color, 1.0);
}
