#version 450 core
// Material classification of the visibility buffer: one work group per 8x8
// tile finds the materials its pixels show and appends the tile to each one's
// list (material_tiles.glsl), so that each material's resolve runs over the
// tiles that hold it with its own textures bound. Pixels that show no geometry
// get the background here, as a lighting pass's would.
#define COMPUTE_STAGE
layout(local_size_x = 8, local_size_y = 8) in;

#include "common/frame.glsl"
#include "common/surface.glsl"
#include "common/lighting_targets.glsl"
#include "visibility/visibility.glsl"
#include "visibility/material_tiles.glsl"

const uint kNone = 0xffffffffu;
shared uint s_material[64];

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  uint slot = gl_LocalInvocationIndex;
  uint material = kNone;
  if (all(lessThan(pixel, ivec2(u_viewport_size)))) {
    uint id = texelFetch(u_visibility, pixel, 0).r;
    if (id == 0u) {
      g_shaded_pixel = pixel;
      write_background();
    } else {
      uint triangle;
      material = visible_instance(id, triangle).material.x;
    }
  }
  s_material[slot] = material;
  barrier();
  if (material == kNone) return;
  // The first pixel of the tile to show a material lists the tile for it.
  for (uint i = 0u; i < slot; ++i) {
    if (s_material[i] == material) return;
  }
  uint index = atomicAdd(u_dispatch[material].x, 1u);
  u_tiles[material * u_tile_capacity + index] = gl_WorkGroupID.x | (gl_WorkGroupID.y << 16);
}
