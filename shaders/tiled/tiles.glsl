// The screen tiles of tiled-deferred: 16x16 pixels each, and what
// tile_bounds.comp learnt of each for assign.comp. C++: TiledTechnique.
struct TileBounds {
  vec4 planes[4];  // side planes through the eye, normals inward (view space)
  vec4 depths;     // x nearest, y farthest view depth of what the tile holds; z 1 when it holds nothing
};
layout(std430, binding = 4) buffer TileBoundsBlock { TileBounds u_tile_bounds[]; };
uniform uvec2 u_tiles;
