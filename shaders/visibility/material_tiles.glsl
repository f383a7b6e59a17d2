// The material classification's output: per material, an indirect dispatch
// (x counts the tiles that hold it) and the list of those tiles, each the
// size of classify.comp's work group and packed as x | y << 16. C++ twin:
// DispatchCommand in src/render/techniques/visibility/visibility.hpp.

struct Dispatch {
  uint x, y, z;
};
layout(std430, binding = 27) buffer MaterialDispatch { Dispatch u_dispatch[]; };
layout(std430, binding = 28) buffer MaterialTileLists { uint u_tiles[]; };
// A material's list starts at its index times this: every tile of the frame,
// each a work group of classify.comp (and of the resolve, which shares its size).
uint tile_capacity() {
  uvec2 tiles = (uvec2(u_viewport_size) + gl_WorkGroupSize.xy - 1u) / gl_WorkGroupSize.xy;
  return tiles.x * tiles.y;
}
