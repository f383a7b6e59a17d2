// The targets a deferred lighting pass writes (FrameTargets::lighting_framebuffer):
// the HDR colour and, with SPLIT_LIGHTING, the diffuse and specular light sums
// apart, which the diffuse-light and specular-light debug views show.
#include "shading.glsl"

layout(location = 0) out vec4 out_color;
#ifdef SPLIT_LIGHTING
layout(location = 1) out vec4 out_diffuse;
layout(location = 2) out vec4 out_specular;
#endif

void write_lighting(vec3 unlit, LightSum sum) {
  out_color = vec4(unlit + light_total(sum), 1.0);
#ifdef SPLIT_LIGHTING
  out_diffuse = vec4(sum.diffuse, 1.0);
  out_specular = vec4(sum.specular, 1.0);
#endif
}

// A pixel no surface covers: the background, and no light.
void write_background() { write_lighting(u_background.rgb, no_light()); }
