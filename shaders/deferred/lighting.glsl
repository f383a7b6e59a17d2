// Deferred lighting: reads each pixel's surface from the G-buffer and loops
// over every light. With LIGHT_RADIUS_CULL (mode deferred-radius) a light whose
// radius does not reach the pixel is skipped; the falloff is already zero
// there, so the picture does not change. Built as a full-screen fragment pass
// (lighting.frag) or a compute pass (lighting.comp), --lighting-stage.
#include "common/frame.glsl"
#include "common/surface.glsl"
#include "common/gbuffer.glsl"
#include "common/lighting_targets.glsl"

void shade_pixel(ivec2 pixel) {
  Surface s;
  if (!read_gbuffer(pixel, s)) {
    write_background();
    return;
  }
  vec3 v = normalize(u_camera_position.xyz - s.position);
  LightSum sum = no_light();
  add_buffer_lights(sum, s, v);
  write_lighting(shade_unlit_terms(s, u_ambient.rgb), sum);
}

#include "common/lighting_main.glsl"
