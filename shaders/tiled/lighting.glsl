// Tiled deferred lighting: reads each pixel's surface from the G-buffer and
// shades it with the lights listed for its 16x16 tile. Built as a full-screen
// fragment pass (lighting.frag) or a compute pass (lighting.comp), whose 8x8
// groups each lie in one tile and so loop over one list together.
#include "common/frame.glsl"
#include "common/surface.glsl"
#include "common/gbuffer.glsl"
#include "common/tile_shading.glsl"
#include "common/lighting_targets.glsl"

void shade_pixel(ivec2 pixel) {
  Surface s;
  if (!read_gbuffer(pixel, s)) {
    write_background();
    return;
  }
  write_lighting(shade_unlit_terms(s, u_ambient.rgb), shade_tile_lights(s, vec2(pixel) + 0.5));
}

#include "common/lighting_main.glsl"
