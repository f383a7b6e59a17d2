#version 450 core
// Each material's list of the tiles that show it, from what the
// classification (classify.comp) counted and kept per tile, in two steps
// (u_step), both in the pass "material classification":
//   kRanges   one work group turns the materials' tile counts into their
//             ranges of the lists (an exclusive prefix sum) and the indirect
//             dispatches of their resolves;
//   kScatter  an invocation per tile writes the tile into the range of each
//             material it shows.
// The lists hold as many entries as the tiles show materials: at most tiles
// times the fewer of the materials and a tile's 64 x samples. A list of every
// tile for each material, which a single pass needs, grows with materials
// times tiles (618.8 MiB for a model of 1,100 materials at 4096x2304).
// C++: VisibilityTechnique::classify.
layout(local_size_x = 256) in;

#include "common/group_scan.glsl"
#include "visibility/material_tiles.glsl"

uniform uint u_step;
uniform uint u_material_count;  // of this frame's draw list
uniform uint u_tile_count;
uniform uint u_tile_columns;

const uint kRanges = 0u, kScatter = 1u;
// GL promises at least this many work groups along each axis of a dispatch.
const uint kMaxGroupsX = 65535u;

// One work group; each invocation takes a run of consecutive materials.
void ranges() {
  uint thread = gl_LocalInvocationIndex, per_thread = (u_material_count + 255u) / 256u;
  uint first = min(thread * per_thread, u_material_count), end = min(first + per_thread, u_material_count), sum = 0u;
  for (uint m = first; m < end; ++m) sum += u_material_tiles[m].tile_count;
  uint total;
  uint offset = group_exclusive_sum(sum, total);
  for (uint m = first; m < end; ++m) {
    uint count = u_material_tiles[m].tile_count;
    // As few rows as hold the range, evenly filled: fewer groups past its
    // end than it has rows.
    uint rows = max((count + kMaxGroupsX - 1u) / kMaxGroupsX, 1u);
    u_material_tiles[m].x = (count + rows - 1u) / rows;
    u_material_tiles[m].y = rows;
    u_material_tiles[m].z = 1u;
    u_material_tiles[m].first_tile = offset;
    u_material_tiles[m].next_tile = offset;
    offset += count;
  }
}

void scatter() {
  uint tile = gl_GlobalInvocationID.x;
  if (tile >= u_tile_count) return;
  uint slots = tile_materials_at(tile), count = u_tile_materials[slots];
  uint column_row = tile % u_tile_columns | (tile / u_tile_columns) << 16;
  for (uint k = 0u; k < count; ++k) {
    uint material = u_tile_materials[slots + 1u + k];
    u_tiles[atomicAdd(u_material_tiles[material].next_tile, 1u)] = column_row;
  }
}

void main() {
  if (u_step == kRanges) ranges();
  else scatter();
}
