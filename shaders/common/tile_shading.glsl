// Shading with a 16x16 screen tile's lights only (tiled-deferred): shared by the
// lighting pass over the G-buffer and the forward pass over blended surfaces,
// each reading the list bound for it.
#include "shading.glsl"
#include "light_lists.glsl"

uniform uvec2 u_tiles;
uniform uint u_list_capacity;

// The sum of the lights in the tile of `s` (the unlit terms are the caller's).
LightSum shade_tile_lights(Surface s, vec2 frag_coord) {
  uvec2 tile = uvec2(frag_coord) / 16u;
  LightRange range = u_light_ranges[tile.y * u_tiles.x + tile.x];
  vec3 v = normalize(u_camera_position.xyz - s.position);
  LightSum sum = no_light();
  uint end = min(range.offset + range.count, u_list_capacity);
  for (uint i = range.offset; i < end; ++i) add_light(sum, s, v, u_lights[u_light_indices[i]]);
  return sum;
}
