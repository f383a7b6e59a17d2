// Deferred lighting: reads each pixel's surface from the G-buffer and loops
// over every light. With LIGHT_RADIUS_CULL (mode deferred-radius) a light whose
// radius does not reach the pixel is skipped; the falloff is already zero
// there, so the picture does not change. Built as a full-screen fragment pass
// (lighting.frag) or a compute pass (lighting.comp), --lighting-stage. Each
// run sums the lights [u_first_light, u_end_light): DeferredTechnique splits
// many lights into runs that each stay short (lights_per_run), the first
// storing the pixel, the others built with ADD_LIGHTS adding their sums to it.
#include "common/frame.glsl"
#include "common/surface.glsl"
#include "common/gbuffer.glsl"
#include "common/lighting_targets.glsl"

uniform uint u_first_light;
uniform uint u_end_light;

void shade_pixel(ivec2 pixel) {
  Surface s;
  if (!read_gbuffer(pixel, s)) {
#ifdef ADD_LIGHTS
    leave_pixel();
#else
    write_background();
#endif
    return;
  }
  vec3 v = normalize(u_camera_position.xyz - s.position);
  LightSum sum = no_light();
  add_light_range(sum, s, v, u_first_light, min(u_end_light, u_light_count), kLightRadiusCull);
#ifdef ADD_LIGHTS
  add_lighting(sum);
#else
  write_lighting(shade_unlit_terms(s, u_ambient.rgb), sum);
#endif
}

#include "common/lighting_main.glsl"
