#version 450 core
// Tiled deferred lighting: reads each pixel's surface from the G-buffer and
// shades it with the lights listed for its 16x16 tile.
#include "common/frame.glsl"
#include "common/surface.glsl"
#include "common/gbuffer.glsl"
#include "common/tile_shading.glsl"

layout(location = 0) out vec4 out_color;

void main() {
  Surface s;
  if (!read_gbuffer(ivec2(gl_FragCoord.xy), s)) {
    out_color = vec4(u_background.rgb, 1.0);
    return;
  }
  out_color = vec4(shade_tile_lights(s, gl_FragCoord.xy), 1.0);
}
