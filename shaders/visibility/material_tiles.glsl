// The material classification's output: per material, an indirect dispatch
// (x counts the tiles that hold it) and the list of those tiles, kTileSize
// pixels square, each packed as x | y << 16. C++ twin: MaterialTiles in
// src/render/techniques/visibility/material_tiles.hpp.
const int kTileSize = 8;

struct Dispatch {
  uint x, y, z;
};
layout(std430, binding = 27) buffer MaterialDispatch { Dispatch u_dispatch[]; };
layout(std430, binding = 28) buffer MaterialTileLists { uint u_tiles[]; };
// A material's list starts at its index times this (every tile, at most).
uniform uint u_tile_capacity;
