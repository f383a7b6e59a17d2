#version 450 core
// Material classification of the visibility buffer: one work group per 8x8
// tile finds the materials its pixels show and appends the tile to each one's
// list (material_tiles.glsl), so that each material's resolve runs over the
// tiles that hold it with its own textures bound. Samples that show no
// geometry get the background here, as a lighting pass's would. With MSAA
// every sample's identifier counts: an edge pixel may show several materials.
#define COMPUTE_STAGE
layout(local_size_x = 8, local_size_y = 8) in;

#include "common/frame.glsl"
#include "common/surface.glsl"
#include "common/lighting_targets.glsl"
#include "visibility/visibility.glsl"
#include "visibility/material_tiles.glsl"
#include "visibility/tile_materials.glsl"

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  uint first = gl_LocalInvocationIndex * uint(kSamples);
  bool inside = all(lessThan(pixel, ivec2(u_viewport_size)));
  uint background = 0u;  // the samples without geometry, a bit each
  for (int i = 0; i < kSamples; ++i) {
    uint material = kNone;
    if (inside) {
      uint id = fetch_sample(u_visibility, pixel, i).r;
      if (id == 0u) {
        background |= 1u << i;
      } else {
        uint triangle;
        material = visible_instance(id, triangle).material.x;
        for (int j = 0; j < i; ++j) material = s_slot_material[first + uint(j)] == material ? kNone : material;
      }
    }
    s_slot_material[first + uint(i)] = material;
  }
  if (background != 0u) {
    g_shaded_pixel = pixel;
#ifdef MSAA_SAMPLES
    g_shaded_samples = background;
#endif
    write_background();
  }
  barrier();
  // The first sample of the tile to show a material lists the tile for it.
  for (int i = 0; i < kSamples; ++i) {
    if (!first_slot_of_its_material(first + uint(i))) continue;
    uint material = s_slot_material[first + uint(i)];
    uint index = atomicAdd(u_dispatch[material].x, 1u);
    u_tiles[material * tile_capacity() + index] = gl_WorkGroupID.x | (gl_WorkGroupID.y << 16);
  }
}
