#version 450 core
// Tiled deferred lighting: reads each pixel's surface from the G-buffer and
// shades it with the lights listed for its 16x16 tile.
#include "common/frame.glsl"
#include "common/surface.glsl"
#include "common/gbuffer.glsl"
#include "common/shading.glsl"
#include "common/light_lists.glsl"

uniform uvec2 u_tiles;
uniform uint u_list_capacity;

layout(location = 0) out vec4 out_color;

void main() {
  Surface s;
  if (!read_gbuffer(ivec2(gl_FragCoord.xy), s)) {
    out_color = vec4(u_background.rgb, 1.0);
    return;
  }
  uvec2 tile = uvec2(gl_FragCoord.xy) / 16u;
  LightRange range = u_light_ranges[tile.y * u_tiles.x + tile.x];
  vec3 v = normalize(u_camera_position.xyz - s.position);
  vec3 color = shade_unlit_terms(s, u_ambient.rgb);
  uint end = min(range.offset + range.count, u_list_capacity);
  for (uint i = range.offset; i < end; ++i) color += shade_light(s, v, u_lights[u_light_indices[i]]);
  out_color = vec4(color, 1.0);
}
