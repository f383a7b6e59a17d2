#version 450 core
// Reads the depth buffer after the first geometry pass (every sample with
// MSAA); writes the farthest view depth of each 8x8-pixel tile (infinity where
// some sample holds no geometry): the finest level of occlusion culling's depth
// pyramid, read back for the CPU or reduced further on the GPU
// (depth_pyramid.comp; src/render/culling/): whatever lies behind it is hidden.
// A work group holds 8 tiles side by side, an invocation one row of a tile:
// the rows meet after one barrier, where a tree over 64 pixels took seven
// (each a switch of every invocation on a software renderer).
layout(local_size_x = 8, local_size_y = 8) in;  // x: the tile, y: its row

#include "common/frame.glsl"
#include "common/msaa.glsl"

layout(binding = 14) uniform target2D u_depth;
layout(std430, binding = 10) writeonly buffer TileDepths { float u_farthest[]; };

uniform uvec2 u_tiles;  // tiles across and down: u_farthest's rows

shared float s_rows[8][8];  // [row][tile]

void main() {
  const uint tile_in_group = gl_LocalInvocationID.x, row = gl_LocalInvocationID.y;
  const ivec2 tile = ivec2(gl_WorkGroupID.x * 8u + tile_in_group, gl_WorkGroupID.y);
  const ivec2 size = ivec2(u_viewport_size), tiles = ivec2(u_tiles);
  // Reversed Z: the farthest sample has the smallest depth. Pixels past the
  // viewport's edge hide nothing and are left out (the near plane's depth).
  float farthest = kDepthNear;
  const ivec2 first = tile * 8 + ivec2(0, int(row));
  if (tile.x < tiles.x && first.y < size.y) {
    for (int x = first.x; x < min(first.x + 8, size.x); ++x) {
      for (int i = 0; i < kSamples; ++i) farthest = min(farthest, fetch_sample(u_depth, ivec2(x, first.y), i).r);
    }
  }
  s_rows[row][tile_in_group] = farthest;
  barrier();
  if (row != 0u || tile.x >= tiles.x) return;
  for (int r = 1; r < 8; ++r) farthest = min(farthest, s_rows[r][tile_in_group]);
  u_farthest[tile.y * tiles.x + tile.x] = farthest <= kDepthFar ? uintBitsToFloat(0x7f800000u) : view_depth_from_depth(farthest);
}
