#version 450 core
// Material classification of the visibility buffer: one work group per 8x8
// tile finds the materials its pixels show, keeps them in the tile's slots
// and counts the tile for each (material_tiles.glsl); material_lists.comp
// then turns the counts into each material's list of tiles, over which its
// resolve runs with its own textures bound. Samples that show no geometry get
// the background here, as a lighting pass's would. With MSAA every sample's
// identifier counts: an edge pixel may show several materials.
#define COMPUTE_STAGE
layout(local_size_x = 8, local_size_y = 8) in;

#include "common/frame.glsl"
#include "common/surface.glsl"
#include "common/lighting_targets.glsl"
#include "visibility/visibility.glsl"
#include "visibility/material_tiles.glsl"
#include "visibility/tile_materials.glsl"

shared uint s_tile_material_count;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  uint first = gl_LocalInvocationIndex * uint(kSamples);
  bool inside = all(lessThan(pixel, ivec2(u_viewport_size)));
  uint background = 0u;  // the samples without geometry, a bit each
  if (gl_LocalInvocationIndex == 0u) s_tile_material_count = 0u;
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
  // The first sample of the tile to show a material counts the tile for it.
  uint slots = tile_materials_at(gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x);
  for (int i = 0; i < kSamples; ++i) {
    if (!first_slot_of_its_material(first + uint(i))) continue;
    uint material = s_slot_material[first + uint(i)];
    atomicAdd(u_material_tiles[material].tile_count, 1u);
    u_tile_materials[slots + 1u + atomicAdd(s_tile_material_count, 1u)] = material;
  }
  barrier();
  if (gl_LocalInvocationIndex == 0u) u_tile_materials[slots] = s_tile_material_count;
}
