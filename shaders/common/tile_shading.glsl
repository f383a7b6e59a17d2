// Shading with a 16x16 screen tile's lights only (tiled-deferred): shared by the
// lighting pass over the G-buffer and the forward pass over blended surfaces,
// each reading the list bound for it.
#include "list_shading.glsl"

uniform uvec2 u_tiles;

// The sum of the lights in the tile of `s` (the unlit terms are the caller's).
LightSum shade_tile_lights(Surface s, vec2 frag_coord) {
  uvec2 tile = uvec2(frag_coord) / 16u;
  return shade_listed_lights(s, light_range(tile.y * u_tiles.x + tile.x));
}
