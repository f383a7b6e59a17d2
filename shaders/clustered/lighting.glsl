// Clustered deferred lighting: reads each pixel's surface from the G-buffer,
// finds its cluster from screen position and view depth, and shades it with
// that cluster's lights only. Built as a full-screen fragment pass
// (lighting.frag) or a compute pass (lighting.comp).
#include "common/frame.glsl"
#include "common/surface.glsl"
#include "common/gbuffer.glsl"
#include "common/cluster_shading.glsl"
#include "common/lighting_targets.glsl"

void shade_pixel(ivec2 pixel) {
  Surface s;
  if (!read_gbuffer(pixel, s)) {
    write_background();
    return;
  }
  write_lighting(shade_unlit_terms(s, u_ambient.rgb), shade_cluster_lights(s, vec2(pixel) + 0.5));
}

#include "common/lighting_main.glsl"
